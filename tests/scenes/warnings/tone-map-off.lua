-- gr.tone_map in a build whose chapter 12 is switched off: the scene loads, writes the clipped
-- film, and says why.
-- rt-args: --features=all,-tone_map
-- expect-warning: tone map (gr.tone_map, tone_map, exposure or srgb) is ignored
-- expect-warning: --features switched it off
gr.tone_map{operator = 'global'}
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
