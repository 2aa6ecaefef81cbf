-- The script fails after gr.render was called: rendering starts only after the script has
-- run, so no image may be written.
-- expect: boom
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light})
error('boom') --!
