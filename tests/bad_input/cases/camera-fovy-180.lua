-- A field of view of 180 degrees.
-- expect: fovy must be between 0 and 180 degrees
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 180, {0.1, 0.1, 0.1}, {light}) --!
