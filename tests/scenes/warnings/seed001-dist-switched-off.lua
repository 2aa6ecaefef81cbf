-- Seed 001's dist = 2 (glossy samples) while --features switches chapter 7 off.
-- rt-args: --features=-glossy
-- expect-warning: dist argument (glossy samples) is ignored
-- expect-warning: --features switched it off
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}, --!
          0, 0, 2, {0, 1, 0})
