-- batch-expect: error
-- Broken: names a mesh file that the student forgot to hand in.
local root = gr.node('root')
local pot = gr.mesh('pot', 'utah-teapot.obj')
pot:set_material(gr.material({0.7, 0.7, 0.75}, {0.5, 0.5, 0.5}, 40))
root:add_child(pot)
gr.render(root, 'teapot.png', 64, 48, {0, 1, 6}, {0, -0.1, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})
