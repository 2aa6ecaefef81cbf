-- needs-feature: csg
-- node:csg makes the other node an operand under this one: an other node that contains this
-- one would make a cycle.
-- expect: node:csg: 'b' contains 'a', so combining them would make a cycle in the scene graph
local a = gr.node('a')
local b = gr.node('b')
b:add_child(a)
a:csg(b, 'd') --!
