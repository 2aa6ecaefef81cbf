-- A node made its own child.
-- expect: would make a cycle
local a = gr.node('a')
a:add_child(a) --!
