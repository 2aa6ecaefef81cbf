-- gr.render with an empty light list.
-- expect: (lights) is empty
local root = gr.sphere('s')
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {}) --!
