-- rt-era: legacy
-- rt-same-as: ../a4/simple.lua
-- simple-2013.lua: scenes/a4/simple.lua as a student had it before 2015 (Lua 5.1 course
-- framework). rt tells its era from the table mesh, so it needs no flag, and it must give
-- exactly the picture of ../a4/simple.lua.
--
-- How it differs from the current sample:
--  * the dodecahedron is given inline as Lua tables, gr.mesh(name, vertices, faces), with
--    faces counting vertices from 0 (the same vertices and corners as ../a4/dodeca.obj);
--  * the old framework post-multiplied transforms, so the one transformed node, the
--    dodecahedron, lists its calls last-applied first: translate, rotate y, rotate x, scale
--    means "scale, then turn about x, then about y, then move".

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

b1 = gr.nh_box('b1', {-200, -125, 0}, 100)
scene_root:add_child(b1)
b1:set_material(mat4)

s4 = gr.nh_sphere('s4', {-100, 25, -300}, 50)
scene_root:add_child(s4)
s4:set_material(mat3)

-- A dodecahedron of circumradius sqrt(3): 20 corners and 12 pentagons, indices from 0.
a = 0.618033988749895   -- 1/phi
b = 1.618033988749895   -- phi
poly = gr.mesh('poly', {
    {-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {-1, 1, 1},
    { 1, -1, -1}, { 1, -1, 1}, { 1, 1, -1}, { 1, 1, 1},
    {0, -a, -b}, {-a, -b, 0}, {-b, 0, -a}, {0, -a, b},
    {-a, b, 0}, {-b, 0, a}, {0, a, -b}, {a, -b, 0},
    {b, 0, -a}, {0, a, b}, {a, b, 0}, {b, 0, a}
  }, {
    {13, 10, 0, 9, 1}, {14, 8, 0, 10, 2}, {15, 9, 0, 8, 4},
    {3, 13, 1, 11, 17}, {5, 11, 1, 9, 15}, {3, 12, 2, 10, 13},
    {6, 14, 2, 12, 18}, {18, 12, 3, 17, 7}, {5, 15, 4, 16, 19},
    {6, 16, 4, 8, 14}, {17, 11, 5, 19, 7}, {19, 16, 6, 18, 7}
  })
scene_root:add_child(poly)
poly:set_material(mat3)
poly:translate(0, -110, 120)
poly:rotate('y', 20)
poly:rotate('x', 30)
poly:scale(40, 40, 40)

white_light = gr.light({-100.0, 150.0, 400.0}, {0.9, 0.9, 0.9}, {1, 0, 0})
magenta_light = gr.light({400.0, 100.0, 150.0}, {0.7, 0.0, 0.7}, {1, 0, 0})

gr.render(scene_root, 'simple.png', 256, 256,
          {0, 0, 800}, {0, 0, -800}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {white_light, magenta_light})
