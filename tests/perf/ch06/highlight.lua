-- Chapter 6's highlight close-up (tests/perf/ch06/charts.sh): a shiny black sphere under a
-- long rectangular panel and a small ball light. With point lights (chapter 6 off) both
-- highlights are round dots; with area lights the panel's highlight is its rectangle, seen in
-- a curved mirror and blurred by the Phong lobe, and the ball's stays round.
local black = gr.material{kd = {0.03, 0.03, 0.035}, ks = {0.9, 0.9, 0.9}, shininess = 300}
local floorM = gr.material{kd = {0.2, 0.2, 0.22}, ks = {0, 0, 0}, shininess = 1}

local root = gr.node('root')
local ball = gr.nh_sphere('shiny', {0, 1, 0}, 1)
ball:set_material(black)
root:add_child(ball)
local floor = gr.cube('floor')
floor:scale(20, 1, 20)
floor:translate(-10, -1, -10)
floor:set_material(floorM)
root:add_child(floor)

local panel = gr.area_light{position = {0, 3.2, 2.6}, colour = {70, 70, 70},
                            falloff = {0, 0, 1}, size = {4, 1.2},
                            normal = {0, -0.6, -0.8}, left = {1, 0, 0}}
local bulb = gr.ball_light{position = {-3, 2.5, 2}, colour = {6, 4.2, 2.1},
                           falloff = {0, 0, 1}, radius = 0.3}

gr.render(root, 'highlight.png', 256, 192, {0, 1.6, 4.2}, {0, -0.15, -1}, {0, 1, 0}, 35,
          {0.05, 0.05, 0.05}, {panel, bulb})
