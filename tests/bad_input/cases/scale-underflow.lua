-- Tiny scales that multiply to a singular world transform (1e-120 cubed underflows to 0).
-- expect: node 'dust' has a singular or non-finite transform
local root = gr.node('root')
root:scale(1e-120, 1e-120, 1e-120)
local dust = gr.sphere('dust')
dust:scale(1e-120, 1e-120, 1e-120)
root:add_child(dust)
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
