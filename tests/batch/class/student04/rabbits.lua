-- batch-expect: ok
-- Seed 002's dialect, two views of the same glazed cones: two gr.render calls, two images.
local glaze = gr.fancy_material({0.2, 0.35, 0.55}, {0.7, 0.7, 0.7}, 90, 0.2, 1.0, 0, 0)
local clay  = gr.fancy_material({0.7, 0.5, 0.35}, {0.1, 0.1, 0.1}, 5, 0, 1.0, 0, 0)

local root = gr.node('root')
local base = gr.cube('base')
base:scale(6, 0.3, 6)
base:translate(-3, -0.3, -3)
base:set_material(clay)
root:add_child(base)
for i = 1, 3 do
  local c = gr.obj_mesh('cone' .. i, 'cone.obj')
  c:scale(0.4, 0.5, 0.4)
  c:translate((i - 2) * 1.3, 0, 0)
  c:set_material(glaze)
  root:add_child(c)
end
local lights = {gr.ball_light({2, 4, 3}, {0.9, 0.9, 0.9}, {1, 0, 0}, 0.3)}
gr.render(root, 'rabbits-front.png', 120, 90, {0, 1.5, 5}, {0, -0.25, -1}, {0, 1, 0}, 45,
          {0.2, 0.2, 0.2}, lights)
gr.render(root, 'rabbits-top.png', 120, 90, {0, 6, 0.01}, {0, -1, 0}, {0, 0, -1}, 45,
          {0.2, 0.2, 0.2}, lights)
