-- simple-cows.lua: cows made of spheres, in the spirit of the CS488 A4 sample. One cow node
-- (ten non-hierarchical spheres) is instanced three times, each copy with its own scale,
-- turn ('Y', the capital form of the axis name) and position, around a stone arch.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/simple-cows.lua   (writes simple-cows.png)

stone = gr.material({0.8, 0.7, 0.7}, {0.0, 0.0, 0.0}, 0)
grass = gr.material({0.1, 0.7, 0.1}, {0.0, 0.0, 0.0}, 0)
hide  = gr.material({0.84, 0.6, 0.53}, {0.3, 0.3, 0.3}, 20)
spots = gr.material({0.25, 0.2, 0.2}, {0.2, 0.2, 0.2}, 10)

-- The cow: a big body sphere, a head, a snout, four legs, a tail and two spots. It faces +x,
-- its hooves reach down to y = -1.65 in its own frame, so the copies below lift it by 1.65.
cow = gr.node('the_cow')
for _, spec in ipairs({
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
  }) do
  local name, centre, radius, mat = table.unpack(spec)
  local part = gr.nh_sphere(name, centre, radius)
  part:set_material(mat)
  cow:add_child(part)
end
-- Hooves: a squashed sphere under each leg.
for i, at in ipairs({{0.7, -0.7}, {-0.7, -0.7}, {0.7, 0.7}, {-0.7, 0.7}}) do
  local hoof = gr.sphere('hoof' .. i)
  hoof:scale(0.22, 0.45, 0.22)
  hoof:translate(at[1], -1.2, at[2])
  hoof:set_material(spots)
  cow:add_child(hoof)
end

scene = gr.node('scene')
scene:rotate('X', 23)  -- tilt the whole world towards the camera

-- The ground.
plane = gr.cube('plane')
plane:scale(60, 1, 60)
plane:translate(-30, -1, -30)
plane:set_material(grass)
scene:add_child(plane)

-- The arch: two pillars and a lintel.
arc = gr.node('arc')
arc:rotate('Y', 60)
arc:translate(0, 0, -10)
scene:add_child(arc)
for _, x in ipairs({-2.4, 1.6}) do
  local pillar = gr.cube('pillar')
  pillar:scale(0.8, 4, 0.8)
  pillar:translate(x, 0, -0.4)
  pillar:set_material(stone)
  arc:add_child(pillar)
end
lintel = gr.cube('lintel')
lintel:scale(5.2, 0.8, 1.0)
lintel:translate(-2.6, 4, -0.5)
lintel:set_material(stone)
arc:add_child(lintel)

-- Three copies of the one cow.
for i, p in ipairs({{{1, 0, 4}, 20, 1.4}, {{5, 0, -11}, 180, 1.0}, {{-5.5, 0, -3}, -60, 1.2}}) do
  local copy = gr.node('cow' .. i)
  copy:translate(0, 1.65, 0)     -- hooves onto the ground (in the cow's own units)
  copy:scale(p[3], p[3], p[3])
  copy:rotate('Y', p[2])
  copy:translate(table.unpack(p[1]))
  copy:add_child(cow)
  scene:add_child(copy)
end

gr.render(scene, 'simple-cows.png', 320, 320,
          {0, 2, 22}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.4, 0.4, 0.4}, {gr.light({200, 202, 430}, {0.8, 0.8, 0.8}, {1, 0, 0})})
