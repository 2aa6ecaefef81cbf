-- Seed 001's gr.render with aa = 1 in a build with chapter 8 on: the 2 x 2 supersample is
-- made, so there is nothing to warn about.
-- expect-no-warning
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}, --!
          1, 0, 0, {0, 1, 0})
