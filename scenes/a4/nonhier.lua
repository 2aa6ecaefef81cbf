-- nonhier.lua: a CS488 A4 scene made only of non-hierarchical primitives (gr.nh_sphere and
-- gr.nh_box, placed by their own arguments) and one OBJ mesh, the exact dodecahedron. No
-- node is transformed: everything sits where its arguments put it.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/nonhier.lua   (writes nonhier.png)

gold  = gr.material({0.9, 0.8, 0.4}, {0.8, 0.8, 0.4}, 25)
grass = gr.material({0.1, 0.7, 0.1}, {0.0, 0.0, 0.0}, 0)
blue  = gr.material({0.7, 0.6, 1.0}, {0.5, 0.4, 0.8}, 25)
red   = gr.material({0.9, 0.2, 0.15}, {0.6, 0.6, 0.6}, 60)
stone = gr.material({0.65, 0.6, 0.55}, {0.1, 0.1, 0.1}, 5)

scene = gr.node('scene')

-- A 20-unit cube whose top face is the ground at y = -1.8 (nh_box takes the minimum corner).
ground = gr.nh_box('ground', {-10, -21.8, -14}, 20)
ground:set_material(grass)
scene:add_child(ground)

-- The dodecahedron, centred at the origin with circumradius sqrt(3) ~ 1.73, as the file
-- gives it.
dodeca = gr.mesh('dodeca', 'dodeca.obj')
dodeca:set_material(gold)
scene:add_child(dodeca)

-- Four spheres around it, each resting on the ground.
for i, s in ipairs({{-3.2, 0.8, blue}, {3.0, 1.0, red}, {-1.6, 0.45, red}, {1.9, 0.5, blue}}) do
  local z = (i <= 2) and -1.5 or 2.2
  local ball = gr.nh_sphere('ball' .. i, {s[1], -1.8 + s[2], z}, s[2])
  ball:set_material(s[3])
  scene:add_child(ball)
end

-- A stack of three boxes at the back, each given by its minimum corner and edge length.
local y = -1.8
for i, size in ipairs({1.6, 1.1, 0.6}) do
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
