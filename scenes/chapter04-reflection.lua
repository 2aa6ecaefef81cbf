-- Chapter 4: mirror reflection. Two facing mirrors repeat a red ball many times (each image
-- is dimmer by the reflectivity), and a chrome sphere reflects the room. Materials use
-- raybook's named fields; gr.option sets the recursion limit.
gr.option('max_depth', 8)

local mirror = gr.material{kd = {0.02, 0.02, 0.02}, ks = {0.2, 0.2, 0.2}, shininess = 50,
                           reflect = 0.85}
local chrome = gr.material{kd = {0.1, 0.1, 0.12}, ks = {0.8, 0.8, 0.8}, shininess = 120,
                           reflect = 0.7}
local red    = gr.material{kd = {0.8, 0.12, 0.1}, ks = {0.5, 0.5, 0.5}, shininess = 30}
local floorM = gr.material{kd = {0.5, 0.5, 0.45}, ks = {0, 0, 0}, shininess = 1,
                           reflect = 0.15}
local wall   = gr.material{kd = {0.35, 0.45, 0.6}, ks = {0, 0, 0}, shininess = 1}

local scene = gr.node('root')

local floor = gr.cube('floor')
floor:scale(40, 1, 40)
floor:translate(-20, -2, -30)
floor:set_material(floorM)
scene:add_child(floor)

local back = gr.cube('back')
back:scale(40, 20, 1)
back:translate(-20, -1, -12)
back:set_material(wall)
scene:add_child(back)

-- Two parallel mirrors facing each other across x.
for _, x in ipairs({-4.2, 4}) do
  local m = gr.cube('mirror')
  m:scale(0.2, 4, 6)
  m:translate(x, -1, -5)
  m:set_material(mirror)
  scene:add_child(m)
end

local ball = gr.nh_sphere('ball', {-1.6, -0.2, -2.5}, 0.8)
ball:set_material(red)
scene:add_child(ball)

local chromeBall = gr.nh_sphere('chrome', {1.4, 0.1, -3.2}, 1.1)
chromeBall:set_material(chrome)
scene:add_child(chromeBall)

local key  = gr.light({-2, 6, 4}, {0.9, 0.9, 0.85}, {1, 0, 0})
local fill = gr.light({3, 3, 6}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'chapter04-reflection.png', 256, 192,
          {0, 1.2, 6}, {0, -0.15, -1}, {0, 1, 0}, 55,
          {0.2, 0.2, 0.2}, {key, fill})
