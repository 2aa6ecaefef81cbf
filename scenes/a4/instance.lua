-- rt-stats: instances +199$
-- instance.lua: instancing in the CS488 A4 scene graph. One column subtree (four shapes,
-- one of them a mesh) is added under eight parents to make a colonnade; the colonnade is
-- added twice to make a two-storey pavilion; the pavilion is added three times to make the
-- scene. The graph is a DAG: 4 shapes are drawn as 4 x 8 x 2 x 3 = 192 instances, plus the
-- roofs and the ground. Each instance's transform lives on the node above the shared subtree.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/instance.lua   (writes instance.png)

stone  = gr.material({0.85, 0.82, 0.75}, {0.3, 0.3, 0.3}, 20)
dark   = gr.material({0.55, 0.5, 0.45}, {0.1, 0.1, 0.1}, 5)
gem    = gr.material({0.2, 0.6, 0.9}, {0.9, 0.9, 0.9}, 120)
roofm  = gr.material({0.7, 0.25, 0.2}, {0.3, 0.3, 0.3}, 15)
ground = gr.material({0.35, 0.55, 0.3}, {0.0, 0.0, 0.0}, 1)

-- The column: a plinth, a shaft, a capital and an icosahedron on top. 2.4 units tall, its
-- foot centred on the origin.
column = gr.node('column')

base = gr.nh_box('base', {-0.25, 0, -0.25}, 0.5)
base:set_material(dark)
column:add_child(base)

shaft = gr.sphere('shaft')
shaft:scale(0.15, 0.9, 0.15)
shaft:translate(0, 1.3, 0)
shaft:set_material(stone)
column:add_child(shaft)

capital = gr.cube('capital')
capital:scale(0.5, 0.2, 0.5)
capital:translate(-0.25, 2.1, -0.25)
capital:set_material(dark)
column:add_child(capital)

finial = gr.mesh('finial', 'icosa.obj')
finial:scale(0.1, 0.1, 0.1)
finial:translate(0, 2.5, 0)
finial:set_material(gem)
column:add_child(finial)

-- A ring of eight columns of radius 2: the same column node under eight parents.
colonnade = gr.node('colonnade')
for i = 0, 7 do
  local place = gr.node('place' .. i)
  place:translate(2, 0, 0)
  place:rotate('y', 45 * i)
  place:add_child(column)
  colonnade:add_child(place)
end

-- A pavilion: the colonnade, a roof slab, and a smaller copy of the colonnade on the roof.
pavilion = gr.node('pavilion')
pavilion:add_child(colonnade)
roof = gr.sphere('roof')
roof:scale(2.7, 0.15, 2.7)
roof:translate(0, 2.75, 0)
roof:set_material(roofm)
pavilion:add_child(roof)
upper = gr.node('upper')
upper:scale(0.5, 0.5, 0.5)
upper:translate(0, 2.9, 0)
upper:add_child(colonnade)
pavilion:add_child(upper)
top = gr.sphere('top')
top:scale(1.45, 0.1, 1.45)
top:translate(0, 4.2, 0)
top:set_material(roofm)
pavilion:add_child(top)

scene = gr.node('scene')
for i, p in ipairs({{0, 0, 0, 1.0, 0}, {-6.5, 0, -5, 0.8, 22.5}, {6, 0, -7, 0.7, 10}}) do
  local copy = gr.node('pavilion' .. i)
  copy:scale(p[4], p[4], p[4])
  copy:rotate('y', p[5])
  copy:translate(p[1], p[2], p[3])
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
