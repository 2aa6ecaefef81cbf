-- add_child given a material instead of a node.
-- expect: node:add_child: argument 2 (child) must be a scene node, got a material
local n = gr.node('n')
n:add_child(gr.material({1, 1, 1}, {0, 0, 0}, 1)) --!
