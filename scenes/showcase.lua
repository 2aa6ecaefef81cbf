-- rt-stats: [^0-9]3730 triangles
-- showcase.lua: the best picture chapters 1-3 can make: Phong materials, point lights with
-- hard shadows, instancing, the Stanford bunny mesh (3,674 triangles, loaded once and drawn
-- five times) and analytic primitives. A gallery: a checkered marble floor of instanced
-- tiles, a golden bunny on a central plinth between four smaller bunnies, a colonnade behind,
-- gems and spheres in front.
--
-- Run from the repository root:  ./build/rt_ch3 scenes/showcase.lua   (writes showcase.png)

local function mat(kd, ks, shininess) return gr.material(kd, ks, shininess) end

local marbleA  = mat({0.78, 0.76, 0.72}, {0.45, 0.45, 0.45}, 80)
local marbleB  = mat({0.30, 0.29, 0.32}, {0.45, 0.45, 0.45}, 80)
local plinthM  = mat({0.62, 0.58, 0.54}, {0.25, 0.25, 0.25}, 30)
local columnM  = mat({0.78, 0.74, 0.68}, {0.2, 0.2, 0.2}, 15)
local goldM    = mat({0.66, 0.46, 0.12}, {0.8, 0.7, 0.45}, 90)
local jadeM    = mat({0.22, 0.62, 0.42}, {0.6, 0.7, 0.6}, 70)
local porcelM  = mat({0.90, 0.88, 0.85}, {0.7, 0.7, 0.7}, 120)
local rubyM    = mat({0.70, 0.08, 0.12}, {0.9, 0.8, 0.8}, 140)
local sapphM   = mat({0.10, 0.22, 0.75}, {0.9, 0.9, 1.0}, 140)
local copperM  = mat({0.72, 0.36, 0.20}, {0.8, 0.6, 0.5}, 60)
local wallM    = mat({0.35, 0.18, 0.16}, {0.0, 0.0, 0.0}, 1)

local scene = gr.node('gallery')

-- The floor: 30 x 20 tiles of two marbles (600 instances of two shared tile nodes).
local tiles = {}
for k, m in ipairs({marbleA, marbleB}) do
  local t = gr.cube('tile' .. k)
  t:scale(0.98, 0.2, 0.98)
  t:translate(0.01, -0.2, 0.01)
  t:set_material(m)
  tiles[k] = t
end
local floor = gr.node('floor')
for i = 0, 29 do
  for j = 0, 19 do
    local place = gr.node('tile_' .. i .. '_' .. j)
    place:translate(i - 15, 0, j - 9)
    place:add_child(tiles[(i + j) % 2 + 1])
    floor:add_child(place)
  end
end
scene:add_child(floor)
-- Grout under the tiles, and a back wall.
local grout = gr.nh_box('grout', {-40, -80.19, -60}, 80)
grout:set_material(mat({0.1, 0.1, 0.1}, {0, 0, 0}, 1))
scene:add_child(grout)
local wall = gr.cube('wall')
wall:scale(40, 14, 1)
wall:translate(-20, -0.2, -10)
wall:set_material(wallM)
scene:add_child(wall)

-- A column: a square base, an ellipsoid shaft and a square capital.
local column = gr.node('column')
local cbase = gr.nh_box('cbase', {-0.45, 0, -0.45}, 0.9)
cbase:set_material(columnM)
column:add_child(cbase)
local shaft = gr.sphere('shaft')
shaft:scale(0.32, 2.6, 0.32)
shaft:translate(0, 3.1, 0)
shaft:set_material(columnM)
column:add_child(shaft)
local capital = gr.cube('capital')
capital:scale(1.0, 0.35, 1.0)
capital:translate(-0.5, 5.5, -0.5)
capital:set_material(columnM)
column:add_child(capital)
for i = -2, 2 do
  local place = gr.node('column' .. i)
  place:translate(3.4 * i, 0, -7.5)
  place:add_child(column)
  scene:add_child(place)
end
local beam = gr.cube('beam')
beam:scale(15, 0.5, 1.2)
beam:translate(-7.5, 5.85, -8.1)
beam:set_material(columnM)
scene:add_child(beam)

-- The bunny (about 9.7 tall, feet at y = 0), loaded once.
local bunny = gr.mesh('bunny', 'scenes/assets/bunny.obj')

-- A plinth with a bunny on it: the plinth's height and the bunny's size and material vary.
local function exhibit(name, x, z, height, size, turn, material)
  local node = gr.node(name)
  local plinth = gr.cube(name .. '-plinth')
  plinth:scale(1.6 * size / 0.2, height, 1.6 * size / 0.2)
  plinth:translate(-0.8 * size / 0.2, 0, -0.8 * size / 0.2)
  plinth:set_material(plinthM)
  node:add_child(plinth)
  local painted = gr.node(name .. '-bunny')
  painted:set_material(material)
  painted:add_child(bunny)
  painted:scale(size, size, size)
  painted:rotate('y', turn)
  painted:translate(0, height, 0)
  node:add_child(painted)
  node:translate(x, 0, z)
  scene:add_child(node)
end
exhibit('centre', 0, -2.2, 0.9, 0.36, 20, goldM)
exhibit('left1', -4.6, -3.2, 0.6, 0.2, 45, jadeM)
exhibit('right1', 4.6, -3.2, 0.6, 0.2, -15, porcelM)
exhibit('left2', -7.4, -5.2, 0.4, 0.16, 70, copperM)
exhibit('right2', 7.4, -5.2, 0.4, 0.16, -60, jadeM)

-- Gems in front: the dodecahedron and icosahedron meshes, and polished spheres.
local dodeca = gr.mesh('dodeca', 'scenes/assets/dodeca.obj')
dodeca:set_material(rubyM)
dodeca:scale(0.42, 0.42, 0.42)
dodeca:rotate('x', 20)
dodeca:translate(-2.2, 0.6, 1.4)
scene:add_child(dodeca)
local icosa = gr.mesh('icosa', 'scenes/assets/icosa.obj')
icosa:set_material(sapphM)
icosa:scale(0.36, 0.36, 0.36)
icosa:rotate('z', 15)
icosa:translate(2.3, 0.62, 1.5)
scene:add_child(icosa)

-- A ring of small spheres around the central plinth: one sphere, many instances.
local pearl = gr.sphere('pearl')
pearl:scale(0.22, 0.22, 0.22)
pearl:translate(0, 0.22, 0)
pearl:set_material(porcelM)
for k = 0, 13 do
  local place = gr.node('pearl' .. k)
  place:translate(2.3, 0, 0)
  place:rotate('y', k * 360 / 14)
  place:translate(0, 0, -2.2)
  place:add_child(pearl)
  scene:add_child(place)
end
for i, s in ipairs({{-5.2, 0.55, 1.2, sapphM}, {5.0, 0.45, 1.0, rubyM}, {-0.2, 0.35, 2.6, goldM}}) do
  local ball = gr.nh_sphere('ball' .. i, {s[1], s[2], s[3]}, s[2])
  ball:set_material(s[4])
  scene:add_child(ball)
end

local key  = gr.light({-9, 14, 12}, {0.85, 0.78, 0.65}, {1, 0, 0})
local fill = gr.light({12, 7, 10}, {0.3, 0.35, 0.5}, {1, 0, 0})
local spot = gr.light({0, 9, 1}, {0.7, 0.7, 0.65}, {0.7, 0.02, 0.004})

gr.render(scene, 'showcase.png', 640, 400,
          {0, 3.4, 10.5}, {0, -0.2, -1}, {0, 1, 0}, 44,
          {0.22, 0.22, 0.25}, {key, fill, spot})
