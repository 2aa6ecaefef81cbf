-- A scene asking for a negative target error.
-- expect: gr.option: 'target_error'
local root = gr.sphere('s')
gr.option('target_error', -0.02) --!
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light})
