-- Chapter 10's chart scene: a checker plane of unit squares (a 400 x 400 floor in the planar
-- mapping) seen from 1 unit above it, running off to the horizon. Near the camera a square
-- covers many pixels; towards the horizon many squares fall into one pixel, whose true value
-- is their average, about half way between the two colours. One ray per pixel picks one
-- square at random-looking places instead: aliasing (moire).
local tiles = gr.material({1, 1, 1}, {0, 0, 0}, 1)
tiles:set_texture(gr.texture{checker = {{0.9, 0.9, 0.9}, {0.1, 0.1, 0.1}}, mapping = 'planar',
                             scale = {400, 400}})
local root = gr.node('root')
local floor = gr.cube('floor')
floor:scale(400, 1, 400)
floor:translate(-200, -2, -399)
floor:set_material(tiles)
root:add_child(floor)
-- The light is far and straight above, so that the floor's shading is even: only the checker
-- varies.
gr.render(root, 'checker_plane.png', 128, 96, {0, 0, 0}, {0, -0.12, -1}, {0, 1, 0}, 40,
          {0.3, 0.3, 0.3}, {gr.light({0, 1e4, -50}, {0.7, 0.7, 0.7}, {1, 0, 0})})
