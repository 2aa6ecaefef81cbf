-- needs-feature: csg
-- A CSG operand's own material is checked like any node's: here its transparency is above 1.
-- expect: material of 'difference(c, a)': transparency must be in [0, 1], got 1.5
local glass = gr.material{kd = {0, 0, 0}, transparency = 1.5, ior = 1.5}
local a = gr.sphere('a')
a:set_material(glass)
local d = gr.difference(gr.cube('c'), a)
root = gr.node('root')
root:add_child(d)
gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})}) --!
