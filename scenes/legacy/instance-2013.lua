-- rt-era: legacy
-- rt-same-as: ../a4/instance.lua
-- rt-stats: instances +199$
-- instance-2013.lua: scenes/a4/instance.lua, the pavilions built from one shared column, as
-- a student had it before 2015 (Lua 5.1 course framework). rt tells its era from the table
-- mesh and unpack, so it needs no flag, and it must give exactly the picture of
-- ../a4/instance.lua, with the same 199 instances.
--
-- How it differs from the current sample:
--  * the icosahedron on each column is given inline as Lua tables, gr.mesh(name, vertices,
--    faces), with faces counting vertices from 0 (the vertices and corners of ../a4/icosa.obj);
--  * transforms post-multiply, so each node lists them last-applied first: 'translate, then
--    scale' means "scale, then translate"; a column's place is 'rotate, then translate':
--    moved out by 2, then turned about the centre;
--  * unpack is the Lua 5.1 global (table.unpack later).

stone  = gr.material({0.85, 0.82, 0.75}, {0.3, 0.3, 0.3}, 20)
dark   = gr.material({0.55, 0.5, 0.45}, {0.1, 0.1, 0.1}, 5)
gem    = gr.material({0.2, 0.6, 0.9}, {0.9, 0.9, 0.9}, 120)
roofm  = gr.material({0.7, 0.25, 0.2}, {0.3, 0.3, 0.3}, 15)
ground = gr.material({0.35, 0.55, 0.3}, {0.0, 0.0, 0.0}, 1)

-- The column: plinth, shaft, capital and an icosahedron on top; 2.4 tall, foot at the origin.
column = gr.node('column')

base = gr.nh_box('base', {-0.25, 0, -0.25}, 0.5)
base:set_material(dark)
column:add_child(base)

shaft = gr.sphere('shaft')
shaft:translate(0, 1.3, 0)
shaft:scale(0.15, 0.9, 0.15)
shaft:set_material(stone)
column:add_child(shaft)

capital = gr.cube('capital')
capital:translate(-0.25, 2.1, -0.25)
capital:scale(0.5, 0.2, 0.5)
capital:set_material(dark)
column:add_child(capital)

-- An icosahedron with edge 2: 12 corners, 20 triangles, indices from 0.
p = 1.618033988749895  -- phi
finial = gr.mesh('finial', {
    {0, -1, -p}, {-1, -p, 0}, {-p, 0, -1}, {0, -1, p}, {-1, p, 0}, {-p, 0, 1},
    {0, 1, -p}, {1, -p, 0}, {p, 0, -1}, {0, 1, p}, {1, p, 0}, {p, 0, 1}
  }, {
    {2, 0, 1}, {1, 0, 7}, {6, 0, 2}, {8, 0, 6}, {7, 0, 8},
    {2, 1, 5}, {5, 1, 3}, {3, 1, 7}, {4, 2, 5}, {6, 2, 4},
    {5, 3, 9}, {11, 3, 7}, {9, 3, 11}, {9, 4, 5}, {6, 4, 10},
    {10, 4, 9}, {8, 6, 10}, {11, 7, 8}, {11, 8, 10}, {10, 9, 11}
  })
finial:translate(0, 2.5, 0)
finial:scale(0.1, 0.1, 0.1)
finial:set_material(gem)
column:add_child(finial)

-- A ring of eight columns of radius 2: the same column node under eight parents.
colonnade = gr.node('colonnade')
for i = 0, 7 do
  local place = gr.node('place' .. i)
  place:rotate('y', 45 * i)
  place:translate(2, 0, 0)
  place:add_child(column)
  colonnade:add_child(place)
end

-- A pavilion: the colonnade, a roof slab, and a half-size colonnade on the roof.
pavilion = gr.node('pavilion')
pavilion:add_child(colonnade)
roof = gr.sphere('roof')
roof:translate(0, 2.75, 0)
roof:scale(2.7, 0.15, 2.7)
roof:set_material(roofm)
pavilion:add_child(roof)
upper = gr.node('upper')
upper:translate(0, 2.9, 0)
upper:scale(0.5, 0.5, 0.5)
upper:add_child(colonnade)
pavilion:add_child(upper)
top = gr.sphere('top')
top:translate(0, 4.2, 0)
top:scale(1.45, 0.1, 1.45)
top:set_material(roofm)
pavilion:add_child(top)

-- Three pavilions: x, y, z, size, turn about y.
scene = gr.node('scene')
pavilions = {{0, 0, 0, 1.0, 0}, {-6.5, 0, -5, 0.8, 22.5}, {6, 0, -7, 0.7, 10}}
for i = 1, #pavilions do
  local x, y, z, size, turn = unpack(pavilions[i])
  local copy = gr.node('pavilion' .. i)
  copy:translate(x, y, z)
  copy:rotate('y', turn)
  copy:scale(size, size, size)
  copy:add_child(pavilion)
  scene:add_child(copy)
end

lawn = gr.nh_box('lawn', {-40, -80, -60}, 80)
lawn:set_material(ground)
scene:add_child(lawn)

sun = gr.light({-10, 20, 12}, {0.8, 0.8, 0.75}, {1, 0, 0})
sky = gr.light({12, 8, 10}, {0.3, 0.3, 0.4}, {1, 0, 0})

gr.render(scene, 'instance.png', 480, 300,
          {0, 4.5, 10.5}, {0, -0.22, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {sun, sky})
