-- simple.lua: a simple CS488 A4 scene. Four non-hierarchical spheres, a box and a
-- dodecahedron mesh, lit by a white and a magenta point light. Course-sized coordinates
-- (hundreds of units) on purpose.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/simple.lua   (writes simple.png)

mat1 = gr.material({0.7, 1.0, 0.7}, {0.5, 0.7, 0.5}, 25)
mat2 = gr.material({0.5, 0.5, 0.5}, {0.5, 0.7, 0.5}, 25)
mat3 = gr.material({1.0, 0.6, 0.1}, {0.5, 0.7, 0.5}, 25)
mat4 = gr.material({0.7, 0.6, 1.0}, {0.5, 0.4, 0.8}, 25)

scene_root = gr.node('root')

s1 = gr.nh_sphere('s1', {0, 0, -400}, 100)
scene_root:add_child(s1)
s1:set_material(mat1)

s2 = gr.nh_sphere('s2', {200, 50, -100}, 150)
scene_root:add_child(s2)
s2:set_material(mat1)

s3 = gr.nh_sphere('s3', {0, -1200, -500}, 1000)
scene_root:add_child(s3)
s3:set_material(mat2)

-- The tuple is the box's minimum corner: this box spans (-200,-125,0)..(-100,-25,100).
b1 = gr.nh_box('b1', {-200, -125, 0}, 100)
scene_root:add_child(b1)
b1:set_material(mat4)

s4 = gr.nh_sphere('s4', {-100, 25, -300}, 50)
scene_root:add_child(s4)
s4:set_material(mat3)

-- The dodecahedron has circumradius sqrt(3); scale it to about 70 units and stand it up.
poly = gr.mesh('poly', 'dodeca.obj')
scene_root:add_child(poly)
poly:set_material(mat3)
poly:scale(40, 40, 40)
poly:rotate('x', 30)
poly:rotate('y', 20)
poly:translate(0, -110, 120)

white_light = gr.light({-100.0, 150.0, 400.0}, {0.9, 0.9, 0.9}, {1, 0, 0})
magenta_light = gr.light({400.0, 100.0, 150.0}, {0.7, 0.0, 0.7}, {1, 0, 0})

gr.render(scene_root, 'simple.png', 256, 256,
          {0, 0, 800}, {0, 0, -800}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {white_light, magenta_light})
