-- a:add_child(b); b:add_child(a) makes a cycle.
-- expect: adding 'a' under 'b' would make a cycle in the scene graph
local a = gr.node('a')
local b = gr.node('b')
a:add_child(b)
b:add_child(a) --!
