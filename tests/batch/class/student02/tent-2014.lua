-- batch-expect: ok
-- A 2014 course scene: a tent read from OBJ text by the objreader.lua helper beside it.
require('objreader')

tent_text = [[
v -1 0 -1.5
v 1 0 -1.5
v 0 1.3 -1.5
v -1 0 1.5
v 1 0 1.5
v 0 1.3 1.5
f 1 3 6 4
f 2 5 6 3
f 1 2 3
f 4 6 5
]]

canvas = gr.material({0.9, 0.75, 0.3}, {0.2, 0.2, 0.2}, 15)
ground = gr.material({0.35, 0.5, 0.3}, {0, 0, 0}, 1)

root = gr.node('root')
verts, faces = obj_tables(tent_text)
tent = gr.mesh('tent', verts, faces)
tent:rotate('y', 30)
tent:set_material(canvas)
root:add_child(tent)

field = gr.cube('field')
field:translate(-10, -1, -10)
field:scale(20, 1, 20)
field:set_material(ground)
root:add_child(field)

gr.render(root, 'tent-2014.png', 160, 120,
          {0, 2.5, 6}, {0, -0.35, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {gr.light({4, 6, 5}, {0.9, 0.85, 0.8}, {1, 0, 0})})
