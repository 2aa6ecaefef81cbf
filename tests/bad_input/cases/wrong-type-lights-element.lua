-- A lights list holding something that is not a light.
-- expect: element 2 is not a light made by gr.light
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light, root}) --!
