-- Chapter 5: refraction. A checkered floor and wall (built from boxes) seen through glass:
-- a glass ball with an air bubble, a glass ball holding a ball of water (nested media: the
-- IOR stack), a thin glass pane that shifts the checks behind it sideways, and a tinted
-- ball that is only partly transparent (seed 001's colour rule) and uses Schlick's formula.
-- Shadow rays are opaque in raybook, so every glass object casts a full, hard shadow.
gr.option('max_depth', 8)

local light  = gr.material{kd = {0.85, 0.82, 0.72}, ks = {0, 0, 0}, shininess = 1}
local dark   = gr.material{kd = {0.12, 0.2, 0.35}, ks = {0, 0, 0}, shininess = 1}
local wallA  = gr.material{kd = {0.75, 0.55, 0.3}, ks = {0, 0, 0}, shininess = 1}
local wallB  = gr.material{kd = {0.2, 0.35, 0.25}, ks = {0, 0, 0}, shininess = 1}

-- Clear glass and water: almost fully transparent, with a faint highlight on the rest.
local glass  = gr.material{kd = {0.05, 0.05, 0.05}, ks = {0.6, 0.6, 0.6}, shininess = 200,
                           ior = 1.5, transparency = 0.95}
local water  = gr.material{kd = {0.02, 0.05, 0.08}, ks = {0, 0, 0}, shininess = 1,
                           ior = 1.33, transparency = 0.97}
local air    = gr.material{kd = {0, 0, 0}, ks = {0, 0, 0}, shininess = 1,
                           ior = 1.0, transparency = 1.0}
-- Seed 001's colour rule: 30% red Phong, 70% split between mirror and refraction; this one
-- uses Schlick's approximation instead of the exact Fresnel equations.
local ruby   = gr.material{kd = {0.7, 0.05, 0.08}, ks = {0.5, 0.5, 0.5}, shininess = 100,
                           ior = 1.7, transparency = 0.7, schlick = true}

local scene = gr.node('root')

-- A checkered floor and back wall: one box per square, so refraction visibly bends the lines.
for i = -8, 7 do
  for k = -7, 2 do
    local tile = gr.nh_box('floor', {i, -2, k}, 1)
    tile:set_material((i + k) % 2 == 0 and light or dark)
    scene:add_child(tile)
  end
  for j = 0, 5 do
    local tile = gr.nh_box('wall', {i, j - 1, -8}, 1)
    tile:set_material((i + j) % 2 == 0 and wallA or wallB)
    scene:add_child(tile)
  end
end

-- A glass ball with an off-centre air bubble.
local ball = gr.nh_sphere('glass ball', {-1.9, 0.12, -1.5}, 1.1)
ball:set_material(glass)
scene:add_child(ball)
local bubble = gr.nh_sphere('air bubble', {-1.6, 0.4, -1.2}, 0.4)
bubble:set_material(air)
scene:add_child(bubble)

-- Water inside glass: the stack tells the water surface it borders glass, not air.
local shell = gr.nh_sphere('glass shell', {1.5, 0.02, -1.2}, 1.0)
shell:set_material(glass)
scene:add_child(shell)
local core = gr.nh_sphere('water', {1.5, 0.02, -1.2}, 0.75)
core:set_material(water)
scene:add_child(core)

-- A thin glass pane standing at an angle: the checks behind it shift but keep their direction.
local pane = gr.cube('pane')
pane:translate(-0.5, 0, -0.5)
pane:scale(1.8, 1.9, 0.3)
pane:rotate('y', 40)
pane:translate(-0.1, -1.05, -3.4)
pane:set_material(glass)
scene:add_child(pane)

-- A partly transparent red ball in front, shaded with Schlick's approximation.
local tinted = gr.nh_sphere('ruby', {-0.15, -0.53, 0.4}, 0.45)
tinted:set_material(ruby)
scene:add_child(tinted)

local key  = gr.light({-4, 7, 5}, {0.85, 0.85, 0.8}, {1, 0, 0})
local fill = gr.light({5, 3, 6}, {0.25, 0.25, 0.3}, {1, 0, 0})

gr.render(scene, 'chapter05-refraction.png', 256, 192,
          {0, 1.3, 5.5}, {0, -0.25, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {key, fill})
