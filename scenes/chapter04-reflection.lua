-- Chapter 4: mirror reflection. Two facing mirrors make a corridor; the camera looks into the
-- right-hand one, which shows the left-hand one, which shows the right-hand one again ...
-- Each image of the red ball is dimmer than the one before by the reflectivity 0.8, and the
-- chain ends after max_depth reflections. A chrome ball and a faintly reflective floor reflect
-- too. Materials use raybook's named fields; gr.option sets the recursion limit.
gr.option('max_depth', 10)

local mirror = gr.material{kd = {0.0, 0.0, 0.0}, ks = {0.3, 0.3, 0.3}, shininess = 80,
                           reflect = 0.8}
local frame  = gr.material{kd = {0.25, 0.18, 0.12}, ks = {0.2, 0.2, 0.2}, shininess = 20}
local chrome = gr.material{kd = {0.05, 0.05, 0.06}, ks = {0.8, 0.8, 0.8}, shininess = 120,
                           reflect = 0.75}
local red    = gr.material{kd = {0.8, 0.12, 0.1}, ks = {0.5, 0.5, 0.5}, shininess = 30}
local green  = gr.material{kd = {0.15, 0.6, 0.2}, ks = {0.4, 0.4, 0.4}, shininess = 30}
local floorM = gr.material{kd = {0.55, 0.52, 0.45}, ks = {0.1, 0.1, 0.1}, shininess = 10,
                           reflect = 0.2}
local wall   = gr.material{kd = {0.35, 0.45, 0.6}, ks = {0, 0, 0}, shininess = 1}

local scene = gr.node('root')

local floor = gr.cube('floor')
floor:scale(60, 1, 60)
floor:translate(-30, -2, -40)
floor:set_material(floorM)
scene:add_child(floor)

local back = gr.cube('back')
back:scale(60, 30, 1)
back:translate(-30, -1, -16)
back:set_material(wall)
scene:add_child(back)

-- Two parallel mirrors facing each other across x, each with a wooden rail on top.
for _, x in ipairs({-3.2, 3}) do
  local m = gr.cube('mirror')
  m:scale(0.2, 3.6, 9)
  m:translate(x, -1, -12)
  m:set_material(mirror)
  scene:add_child(m)
  local top = gr.cube('frame')
  top:scale(0.3, 0.25, 9.2)
  top:translate(x - 0.05, 2.6, -12.1)
  top:set_material(frame)
  scene:add_child(top)
end

local ball = gr.nh_sphere('ball', {0.2, -0.35, -6.0}, 0.65)
ball:set_material(red)
scene:add_child(ball)
local ball2 = gr.nh_sphere('ball2', {-1.2, -0.5, -8.2}, 0.5)
ball2:set_material(green)
scene:add_child(ball2)

local chromeBall = gr.nh_sphere('chrome', {1.5, -0.2, -9.8}, 0.8)
chromeBall:set_material(chrome)
scene:add_child(chromeBall)

local key  = gr.light({-1, 6, 2}, {0.9, 0.9, 0.85}, {1, 0, 0})
local fill = gr.light({2, 2, 4}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'chapter04-reflection.png', 256, 192,
          {-2.4, 0.9, -1.8}, {1, -0.16, -0.95}, {0, 1, 0}, 55,
          {0.2, 0.2, 0.2}, {key, fill})
