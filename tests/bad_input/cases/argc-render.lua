-- gr.render without its lights.
-- expect: gr.render expects 10 to 14 arguments
local root = gr.sphere('s')
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}) --!
