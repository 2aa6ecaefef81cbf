-- batch-expect: ok
-- Seed 002's dialect: gr.fancy_material for every surface, a glowing gr.ball_light lamp and
-- a cone shade read with gr.obj_mesh from cone.obj in this folder.
--                          kd                 ks               shin refl  ior  transp gloss
local wood  = gr.fancy_material({0.45, 0.28, 0.15}, {0.3, 0.3, 0.3}, 30, 0.2, 1.0, 0,   0.1)
local shade = gr.fancy_material({0.9, 0.85, 0.6},  {0.1, 0.1, 0.1}, 10, 0,   1.0, 0,   0)
local glass = gr.fancy_material({0.0, 0.0, 0.0},   {0.8, 0.8, 0.8}, 150, 0,  1.5, 0.9, 0)

local root = gr.node('root')
local desk = gr.cube('desk')
desk:scale(8, 0.5, 6)
desk:translate(-4, -0.5, -4)
desk:set_material(wood)
root:add_child(desk)

local lampshade = gr.obj_mesh('shade', 'cone.obj')
lampshade:scale(0.6, 0.5, 0.6)
lampshade:translate(-1.2, 1.2, -1.5)
lampshade:set_material(shade)
root:add_child(lampshade)

local paperweight = gr.sphere('paperweight')
paperweight:scale(0.45, 0.45, 0.45)
paperweight:translate(0.8, 0.45, -0.5)
paperweight:set_material(glass)
root:add_child(paperweight)

local bulb = gr.ball_light({-1.2, 1.0, -1.5}, {0.8, 0.75, 0.6}, {1, 0, 0}, 0.2)
local fill = gr.light({3, 5, 4}, {0.3, 0.3, 0.35}, {1, 0, 0})
gr.render(root, 'lamp-desk.png', 160, 120,
          {0, 2.2, 4}, {0, -0.45, -1}, {0, 1, 0}, 50,
          {0.15, 0.15, 0.15}, {bulb, fill})
