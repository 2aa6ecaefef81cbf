-- The image goes to a folder that does not exist: the write fails cleanly, leaves no
-- temporary file, and the message says which file and which gr.render call.
-- expect: no-such-dir/out.png
-- expect: does not exist
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'no-such-dir/out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
