-- A NaN field of view.
-- expect: gr.render: argument 8 (fovy) must be finite, got nan
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 0/0, {0.1, 0.1, 0.1}, {light}) --!
