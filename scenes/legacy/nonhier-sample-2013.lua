-- rt-era: legacy
-- rt-same-as: ../a4/nonhier.lua
-- nonhier-sample-2013.lua: scenes/a4/nonhier.lua as a student had it before 2015 (Lua 5.1
-- course framework). (nonhier-2013.lua in this folder is another scene, one whose nh_
-- primitives carry node transforms.) rt tells its era from the table mesh and unpack, so it
-- needs no flag, and it must give exactly the picture of ../a4/nonhier.lua.
--
-- Nothing here is transformed, so the old framework's reversed transform order changes
-- nothing; what is old is the dodecahedron, given inline as Lua tables with faces counting
-- vertices from 0 (the same vertices and corners as ../a4/dodeca.obj), and unpack, the
-- Lua 5.1 global that later became table.unpack.

gold  = gr.material({0.9, 0.8, 0.4}, {0.8, 0.8, 0.4}, 25)
grass = gr.material({0.1, 0.7, 0.1}, {0.0, 0.0, 0.0}, 0)
blue  = gr.material({0.7, 0.6, 1.0}, {0.5, 0.4, 0.8}, 25)
red   = gr.material({0.9, 0.2, 0.15}, {0.6, 0.6, 0.6}, 60)
stone = gr.material({0.65, 0.6, 0.55}, {0.1, 0.1, 0.1}, 5)

scene = gr.node('scene')

-- The ground: a 20-unit cube whose top face is at y = -1.8.
ground = gr.nh_box('ground', {-10, -21.8, -14}, 20)
ground:set_material(grass)
scene:add_child(ground)

-- The dodecahedron, circumradius sqrt(3), centred at the origin: 20 corners, 12 pentagons.
local p, q = 1.618033988749895, 0.618033988749895   -- phi and 1/phi
dodeca = gr.mesh('dodeca', {
    {-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {-1, 1, 1},
    {1, -1, -1}, {1, -1, 1}, {1, 1, -1}, {1, 1, 1},
    {0, -q, -p}, {-q, -p, 0}, {-p, 0, -q}, {0, -q, p},
    {-q, p, 0}, {-p, 0, q}, {0, q, -p}, {q, -p, 0},
    {p, 0, -q}, {0, q, p}, {q, p, 0}, {p, 0, q}
  }, {
    {13, 10, 0, 9, 1}, {14, 8, 0, 10, 2}, {15, 9, 0, 8, 4}, {3, 13, 1, 11, 17},
    {5, 11, 1, 9, 15}, {3, 12, 2, 10, 13}, {6, 14, 2, 12, 18}, {18, 12, 3, 17, 7},
    {5, 15, 4, 16, 19}, {6, 16, 4, 8, 14}, {17, 11, 5, 19, 7}, {19, 16, 6, 18, 7}
  })
dodeca:set_material(gold)
scene:add_child(dodeca)

-- Four spheres resting on the ground: x, radius, material.
balls = {{-3.2, 0.8, blue}, {3.0, 1.0, red}, {-1.6, 0.45, red}, {1.9, 0.5, blue}}
for i = 1, #balls do
  local x, r, mat = unpack(balls[i])
  local z = -1.5
  if i > 2 then z = 2.2 end
  local ball = gr.nh_sphere('ball' .. i, {x, -1.8 + r, z}, r)
  ball:set_material(mat)
  scene:add_child(ball)
end

-- A stack of three boxes at the back.
local y = -1.8
sizes = {1.6, 1.1, 0.6}
for i = 1, #sizes do
  local size = sizes[i]
  local box = gr.nh_box('stack' .. i, {-5.5 - size / 2, y, -6 - size / 2}, size)
  box:set_material(stone)
  scene:add_child(box)
  y = y + size
end

sun  = gr.light({-12, 14, 10}, {0.8, 0.8, 0.8}, {1, 0, 0})
fill = gr.light({8, 4, 12}, {0.35, 0.35, 0.45}, {1, 0, 0})

gr.render(scene, 'nonhier.png', 320, 240,
          {0, 2.5, 11}, {0, -0.25, -1}, {0, 1, 0}, 45,
          {0.25, 0.25, 0.25}, {sun, fill})
