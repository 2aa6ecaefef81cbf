-- Chapter 6: soft shadows. Two lights with an area, and no point light:
--   * a 4 x 1.6 rectangular panel above and in front of the scene, tilted towards it, like a
--     photographer's softbox (raybook's named form of seed 001's area light);
--   * a small warm ball light up at the left (seed 002's gr.ball_light).
-- The ball's shadows have a narrow penumbra that widens with the distance from the occluder
-- (see the pole's shadow, sharp at its foot); the panel's are so soft they are mostly
-- penumbra. The shiny black sphere shows each light's shape in its highlight: a rectangle for
-- the panel, a round dot for the ball. With --features=all,-soft_shadows both lights shrink
-- to points at their centres: hard shadows and two round dots.
-- Physical falloff {0, 0, 1} throughout: a light's colour is its radiant intensity (see
-- chapters/06-soft-shadows.md).
gr.option('light_samples', 8)  -- 8 x 8 points on every area light

local floorM = gr.material{kd = {0.6, 0.58, 0.54}, ks = {0, 0, 0}, shininess = 1}
local wallM  = gr.material{kd = {0.5, 0.56, 0.66}, ks = {0, 0, 0}, shininess = 1}
local black  = gr.material{kd = {0.03, 0.03, 0.035}, ks = {0.9, 0.9, 0.9}, shininess = 100}
local red    = gr.material{kd = {0.75, 0.16, 0.12}, ks = {0.3, 0.3, 0.3}, shininess = 40}
local green  = gr.material{kd = {0.2, 0.6, 0.3}, ks = {0.2, 0.2, 0.2}, shininess = 20}
local wood   = gr.material{kd = {0.6, 0.45, 0.3}, ks = {0.1, 0.1, 0.1}, shininess = 10}

local scene = gr.node('root')

local floor = gr.cube('floor')
floor:scale(30, 1, 30)
floor:translate(-15, -1, -20)
floor:set_material(floorM)
scene:add_child(floor)

local back = gr.cube('back')
back:scale(30, 20, 1)
back:translate(-15, -1, -7)
back:set_material(wallM)
scene:add_child(back)

-- The shiny sphere: its highlights are the lights' reflections, blurred by the Phong lobe.
local shiny = gr.nh_sphere('shiny', {0.5, 1.3, -1.6}, 1.3)
shiny:set_material(black)
scene:add_child(shiny)

-- A ball floating above the floor: its shadow is mostly penumbra.
local floating = gr.nh_sphere('floating', {-2.7, 2.0, -0.6}, 0.55)
floating:set_material(red)
scene:add_child(floating)

-- A block on the floor.
local block = gr.cube('block')
block:scale(1.1, 1.1, 1.1)
block:rotate('y', 30)
block:translate(2.9, 0, -0.6)
block:set_material(green)
scene:add_child(block)

-- A thin pole: its shadow is sharp at its foot and blurs towards its tip.
local pole = gr.cube('pole')
pole:scale(0.15, 3.0, 0.15)
pole:translate(-1.3, 0, -3.6)
pole:set_material(wood)
scene:add_child(pole)

-- The panel. Seed 001 writes the same light as
--   gr.light({0.5, 3.8, 2.4}, {30, 30, 30}, {0, 0, 1}, {4, 1.6}, {0, -0.5, -0.866}, {1, 0, 0})
local panel = gr.area_light{position = {0.5, 3.8, 2.4}, colour = {30, 30, 30},
                            falloff = {0, 0, 1}, size = {4, 1.6},
                            normal = {0, -0.5, -0.866}, left = {1, 0, 0}}
-- The ball: radius 0.3, warm.
local ball = gr.ball_light({-4.5, 4.5, 2}, {22, 15.4, 7.7}, {0, 0, 1}, 0.3)

gr.render(scene, 'chapter06-soft-shadows.png', 256, 192,
          {0, 4.2, 7}, {0, -0.42, -1}, {0, 1, 0}, 48,
          {0.1, 0.1, 0.12}, {panel, ball})
