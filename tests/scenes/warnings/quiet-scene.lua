-- A scene with nothing to warn about: a sphere in view, seed 001's arguments all 0 (off).
-- expect-no-warning
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})},
          0, 0, 0, {0.5, 1, 0})
