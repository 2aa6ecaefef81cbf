-- Chapter 2: the A4 scene language. A hierarchical scene with Phong materials, two point
-- lights with falloff, hard shadows and instancing.
local red   = gr.material({0.8, 0.15, 0.1}, {0.6, 0.6, 0.6}, 40)
local blue  = gr.material({0.1, 0.25, 0.8}, {0.4, 0.4, 0.4}, 15)
local grey  = gr.material({0.6, 0.6, 0.55}, {0.0, 0.0, 0.0}, 1)
local gold  = gr.material({0.75, 0.55, 0.1}, {0.8, 0.8, 0.5}, 80)

local scene = gr.node('root')

local floor = gr.cube('floor')
floor:scale(20, 0.5, 20)
floor:translate(-10, -1.5, -10)
floor:set_material(grey)
scene:add_child(floor)

local ball = gr.sphere('ball')
ball:scale(1.2, 1.2, 1.2)
ball:translate(-1.6, 0.2, 0)
ball:set_material(red)
scene:add_child(ball)

-- A squashed sphere: its normals need the inverse transpose.
local egg = gr.sphere('egg')
egg:scale(0.6, 1.3, 0.6)
egg:rotate('z', 30)
egg:translate(1.8, 0.3, 0.5)
egg:set_material(blue)
scene:add_child(egg)

-- One pillar, three instances.
local pillar = gr.node('pillar')
local shaft = gr.nh_box('shaft', {-0.25, -1, -0.25}, 0.5)
shaft:set_material(gold)
pillar:add_child(shaft)
for i = 0, 2 do
  local p = gr.node('pillar' .. i)
  p:translate(-2 + 2 * i, 0, -3)
  p:add_child(pillar)
  scene:add_child(p)
end
local cap = gr.nh_sphere('cap', {0, 0.3, -3}, 0.45)
cap:set_material(gold)
scene:add_child(cap)

local key  = gr.light({-6, 8, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})
local fill = gr.light({5, 4, 8}, {0.5, 0.5, 0.6}, {1, 0.02, 0.001})

gr.render(scene, 'chapter02-phong.png', 256, 192,
          {0, 2, 8}, {0, -0.25, -1}, {0, 1, 0}, 50,
          {0.15, 0.15, 0.15}, {key, fill})
