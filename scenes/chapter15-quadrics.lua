-- Chapter 15: cylinders and cones. On a checkered floor (boxes): a glass cylinder seen from
-- above, whose top cap and bottom cap refract the checks below it (seed 001 saw its caps black);
-- an open copper tube, whose inside shows through the missing caps; a red cone on its base;
-- a blue frustum (a cone cut off at top radius 0.45), capped; and a green lampshade (an open frustum).
-- Pale blue walls and a ceiling stand around it all, so that what the glass reflects and bends
-- upwards is light, and the cylinder's outline reads (against the black background it did not).
-- Every shape is the unit cylinder or cone (height 2 along y, radius 1) under transforms,
-- written in raybook's own calls: seed 001's gr.cyllinder would mark the scene as pre-2015,
-- whose transforms apply in the reverse order.
gr.option('max_depth', 8)

local light  = gr.material{kd = {0.85, 0.82, 0.72}, ks = {0, 0, 0}, shininess = 1}
local dark   = gr.material{kd = {0.15, 0.22, 0.38}, ks = {0, 0, 0}, shininess = 1}
local glass  = gr.material{kd = {0.03, 0.03, 0.03}, ks = {0.7, 0.7, 0.7}, shininess = 300,
                           ior = 1.5, transparency = 0.95}
local copper = gr.material{kd = {0.72, 0.42, 0.22}, ks = {0.6, 0.5, 0.4}, shininess = 60}
local red    = gr.material{kd = {0.75, 0.12, 0.1}, ks = {0.4, 0.4, 0.4}, shininess = 40}
local blue   = gr.material{kd = {0.15, 0.3, 0.75}, ks = {0.4, 0.4, 0.4}, shininess = 40}
local green  = gr.material{kd = {0.2, 0.6, 0.25}, ks = {0.3, 0.3, 0.3}, shininess = 20}

local scene = gr.node('root')

-- The floor: one box per square, the top at y = 0.
for i = -6, 5 do
  for k = -6, 3 do
    local tile = gr.nh_box('tile', {i * 0.5, -0.5, k * 0.5}, 0.5)
    tile:set_material((i + k) % 2 == 0 and light or dark)
    scene:add_child(tile)
  end
end

-- The glass cylinder, radius 0.5 and length 1.1, lying on its side with
-- a cap towards the camera: the checks behind it show through both caps. It floats a hair
-- above the floor, since a surface in the floor's plane would make two surfaces at one place.
local puck = gr.cylinder('glass')
puck:scale(0.5, 0.55, 0.5)
puck:rotate('x', 90)
puck:translate(0, 0.51, -0.3)
puck:set_material(glass)
scene:add_child(puck)

-- An open copper tube lying on its side: no caps, so the eye sees into it.
local tube = gr.cylinder{name = 'tube', open = true}
tube:scale(0.28, 0.7, 0.28)
tube:rotate('z', 90)
tube:rotate('y', 55)
tube:translate(-1.65, 0.28, -0.9)
tube:set_material(copper)
scene:add_child(tube)

-- A red cone on its base.
local cone = gr.cone{name = 'cone'}
cone:scale(0.4, 0.6, 0.4)
cone:translate(1.55, 0.6, -1.1)
cone:set_material(red)
scene:add_child(cone)

-- A blue frustum, capped.
local frustum = gr.cone{name = 'frustum', top_radius = 0.45}
frustum:scale(0.42, 0.3, 0.42)
frustum:translate(1.25, 0.3, 0.45)
frustum:set_material(blue)
scene:add_child(frustum)

-- A green lampshade: an open frustum, wide end down, seen into through its top.
local shade = gr.cone{name = 'shade', top_radius = 0.5, open = true}
shade:scale(0.42, 0.28, 0.42)
shade:translate(-1.2, 0.29, 0.5)
shade:set_material(green)
scene:add_child(shade)

-- The sky: a wall beyond the floor (reaching below it, since the eye looks down past the floor's
-- far edge), a ceiling above the lights and a wall behind the camera, all one pale blue.
local sky = gr.material{kd = {0.55, 0.68, 0.85}, ks = {0, 0, 0}, shininess = 1}
local far = gr.cube('far wall')
far:scale(40, 34, 1)
far:translate(-20, -5, -6)
far:set_material(sky)
scene:add_child(far)
local ceiling = gr.cube('ceiling')
ceiling:scale(40, 1, 40)
ceiling:translate(-20, 9, -20)
ceiling:set_material(sky)
scene:add_child(ceiling)
local near = gr.cube('near wall')
near:scale(40, 30, 1)
near:translate(-20, -1, 8)
near:set_material(sky)
scene:add_child(near)

local key  = gr.light({-3, 6, 4}, {0.8, 0.8, 0.75}, {1, 0, 0})
local fill = gr.light({4, 3, 5}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'chapter15-quadrics.png', 256, 192,
          {0, 3.0, 3.4}, {0, -3.0, -3.6}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {key, fill})
