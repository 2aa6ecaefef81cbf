-- rt-era: legacy
-- rt-same-as: ../a4/simple-cows.lua
-- simple-cows-2013.lua: scenes/a4/simple-cows.lua, the sphere cows by a stone arch, as a
-- student had it before 2015 (Lua 5.1 course framework). rt tells its era from unpack (the
-- Lua 5.1 global that later became table.unpack), so it needs no flag, and it must give
-- exactly the picture of ../a4/simple-cows.lua.
--
-- The old framework post-multiplied transforms, so every node lists its calls last-applied
-- first. A cow copy reads 'translate to its place, turn, scale, lift by 1.65': it is lifted
-- first (in its own units), then scaled, turned and moved.

stone = gr.material({0.8, 0.7, 0.7}, {0.0, 0.0, 0.0}, 0)
grass = gr.material({0.1, 0.7, 0.1}, {0.0, 0.0, 0.0}, 0)
hide  = gr.material({0.84, 0.6, 0.53}, {0.3, 0.3, 0.3}, 20)
spots = gr.material({0.25, 0.2, 0.2}, {0.2, 0.2, 0.2}, 10)

-- The cow, facing +x: ten spheres (name, centre, radius, material) and four hooves.
cow = gr.node('the_cow')
parts = {
  {'body',   {0, 0, 0},          1.0,  hide},
  {'head',   {0.9, 0.3, 0},      0.6,  hide},
  {'snout',  {1.35, 0.15, 0},    0.3,  spots},
  {'tail',   {-0.94, 0.34, 0},   0.2,  hide},
  {'lfleg',  {0.7, -0.7, -0.7},  0.3,  hide},
  {'lrleg',  {-0.7, -0.7, -0.7}, 0.3,  hide},
  {'rfleg',  {0.7, -0.7, 0.7},   0.3,  hide},
  {'rrleg',  {-0.7, -0.7, 0.7},  0.3,  hide},
  {'spot1',  {-0.2, 0.55, 0.65}, 0.35, spots},
  {'spot2',  {0.3, 0.2, -0.8},   0.3,  spots},
}
for i = 1, #parts do
  local name, centre, radius, mat = unpack(parts[i])
  local part = gr.nh_sphere(name, centre, radius)
  part:set_material(mat)
  cow:add_child(part)
end
hooves = {{0.7, -0.7}, {-0.7, -0.7}, {0.7, 0.7}, {-0.7, 0.7}}
for i = 1, #hooves do
  local x, z = unpack(hooves[i])
  local hoof = gr.sphere('hoof' .. i)
  hoof:translate(x, -1.2, z)
  hoof:scale(0.22, 0.45, 0.22)
  hoof:set_material(spots)
  cow:add_child(hoof)
end

scene = gr.node('scene')
scene:rotate('X', 23)

-- The ground.
plane = gr.cube('plane')
plane:translate(-30, -1, -30)
plane:scale(60, 1, 60)
plane:set_material(grass)
scene:add_child(plane)

-- The arch: two pillars and a lintel, turned by 60 degrees and moved back by 10.
arc = gr.node('arc')
arc:translate(0, 0, -10)
arc:rotate('Y', 60)
scene:add_child(arc)
pillars = {-2.4, 1.6}
for i = 1, #pillars do
  local pillar = gr.cube('pillar')
  pillar:translate(pillars[i], 0, -0.4)
  pillar:scale(0.8, 4, 0.8)
  pillar:set_material(stone)
  arc:add_child(pillar)
end
lintel = gr.cube('lintel')
lintel:translate(-2.6, 4, -0.5)
lintel:scale(5.2, 0.8, 1.0)
lintel:set_material(stone)
arc:add_child(lintel)

-- Three copies of the one cow: place, heading, size.
copies = {{{1, 0, 4}, 20, 1.4}, {{5, 0, -11}, 180, 1.0}, {{-5.5, 0, -3}, -60, 1.2}}
for i = 1, #copies do
  local pos, heading, size = unpack(copies[i])
  local copy = gr.node('cow' .. i)
  copy:translate(unpack(pos))
  copy:rotate('Y', heading)
  copy:scale(size, size, size)
  copy:translate(0, 1.65, 0)
  copy:add_child(cow)
  scene:add_child(copy)
end

gr.render(scene, 'simple-cows.png', 320, 320,
          {0, 2, 22}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.4, 0.4, 0.4}, {gr.light({200, 202, 430}, {0.8, 0.8, 0.8}, {1, 0, 0})})
