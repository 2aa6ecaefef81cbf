-- An up vector parallel to the view direction.
-- expect: up vector is zero or parallel to the view direction
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 0, 3}, 50, {0.1, 0.1, 0.1}, {light}) --!
