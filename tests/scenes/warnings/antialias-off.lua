-- gr.antialias in a build whose chapter 8 is switched off: the scene loads, renders one ray
-- per pixel centre, and says why.
-- rt-args: --features=all,-adaptive_aa
-- expect-warning: antialiasing (gr.antialias or aa_sampler) is ignored
-- expect-warning: --features switched it off
gr.antialias{sampler = 'adaptive'}
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
