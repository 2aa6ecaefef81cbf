-- Seed 001's gr.render with aa = 1, in a build whose chapter 8 (antialiasing) is switched off.
-- rt-args: --features=all,-adaptive_aa
-- expect-warning: aa argument (antialiasing) is ignored
-- expect-warning: chapter 8 (adaptive_aa)
-- expect-warning: --features switched it off
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}, --!
          1, 0, 0, {0, 1, 0})
