-- batch-expect: ok
-- A4, current framework: a scene that writes its images into a subfolder, and one outside its
-- own folder. The student's own renders/cube.png (a deliverable) must survive the batch byte
-- for byte, and nothing may be written outside DIR/raybook-report/.
local root = gr.node('root')
local cube = gr.cube('cube')
cube:translate(-0.5, -0.5, -0.5)
cube:rotate('y', 30)
cube:set_material(gr.material({0.8, 0.5, 0.2}, {0.3, 0.3, 0.3}, 20))
root:add_child(cube)
local light = gr.light({3, 4, 5}, {0.9, 0.9, 0.9}, {1, 0, 0})
gr.render(root, 'renders/cube.png', 64, 48, {0, 1, 4}, {0, -0.25, -1}, {0, 1, 0}, 40,
          {0.2, 0.2, 0.2}, {light})
gr.render(root, '../student10-escape.png', 64, 48, {0, 1, 4}, {0, -0.25, -1}, {0, 1, 0}, 40,
          {0.2, 0.2, 0.2}, {light})
