-- math.huge in the camera position.
-- expect: gr.render: argument 5 (eye) must be a table of 3 numbers, but element 2 is inf
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, math.huge, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
