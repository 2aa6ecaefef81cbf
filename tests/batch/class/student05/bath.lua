-- batch-expect: ok
-- Seed 000's dialect: gr.material with keywords. A water surface ("refract"), a polished
-- deck ("glossy" and "reflect") and a tiled basin.
local tile  = gr.material({0.3, 0.55, 0.6}, {0.2, 0.2, 0.2}, 20)
local water = gr.material({0.05, 0.1, 0.12}, {0.8, 0.8, 0.8}, 120, "refract", 1.33)
local deck  = gr.material({0.5, 0.34, 0.2}, {0.2, 0.2, 0.2}, 30, "glossy", 0.1, "reflect", 0.2)
local duck  = gr.material({0.95, 0.8, 0.1}, {0.4, 0.4, 0.4}, 40)

local root = gr.node('root')
local basin = gr.cube('basin')
basin:scale(4, 1, 3)
basin:translate(-2, -1.2, -2.5)
basin:set_material(tile)
root:add_child(basin)

local surface = gr.cube('surface')
surface:scale(3.6, 0.05, 2.6)
surface:translate(-1.8, -0.3, -2.3)
surface:set_material(water)
root:add_child(surface)

local boards = gr.cube('boards')
boards:scale(10, 0.2, 3)
boards:translate(-5, -0.2, 0.6)
boards:set_material(deck)
root:add_child(boards)

local toy = gr.sphere('duck')
toy:scale(0.3, 0.25, 0.3)
toy:translate(0.4, -0.05, -1)
toy:set_material(duck)
root:add_child(toy)

gr.render(root, 'bath.png', 160, 120,
          {0, 2.5, 4}, {0, -0.6, -1}, {0, 1, 0}, 50,
          {0.25, 0.25, 0.25}, {gr.light({-2, 5, 3}, {0.9, 0.9, 0.85}, {1, 0, 0})})
