-- batch-expect: skipped helper
-- notes.lua: the student's scratch file of settings; it mentions gr.render only in this
-- comment, and --[[ in a long comment: gr.render(root, 'x.png', ...) ]] so it is a helper.
--[[
gr.render(root, 'old.png', 64, 64, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0, 0, 0}, {})
]]
eye = {0, 1, 5}
ambient = {0.2, 0.2, 0.2}
