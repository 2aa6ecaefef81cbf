-- Chapter 8: antialiasing. A checkerboard floor runs off towards the horizon, where its squares
-- become smaller than a pixel; a red ball and a mirror ball stand on it, and a row of thin
-- posts and wires (some thinner than a pixel) stands behind. One ray through each pixel centre
-- would give staircase edges and a shimmering, moire floor; the adaptive sampler traces each
-- pixel's corners and centre and splits a square (down to depth 3, 8 x 8 sub-squares) only where
-- its samples differ by more than 0.1, so the flat wall and the near squares cost about two rays
-- a pixel and the edges up to 145. Compare: --aa=none, --aa=uniform --spp 16,
-- --aa=jittered --spp 16, and --aa-threshold 0.02.
gr.antialias{sampler = 'adaptive', threshold = 0.1, depth = 3}

local white = gr.material({0.85, 0.85, 0.8}, {0.1, 0.1, 0.1}, 10)
local black = gr.material({0.08, 0.08, 0.1}, {0.1, 0.1, 0.1}, 10)
local red   = gr.material({0.8, 0.15, 0.1}, {0.6, 0.6, 0.6}, 50)
local steel = gr.material{kd = {0.05, 0.05, 0.06}, ks = {0.7, 0.7, 0.7}, shininess = 80,
                          reflect = 0.8}
local wallM = gr.material({0.35, 0.45, 0.6}, {0, 0, 0}, 1)
local postM = gr.material({0.95, 0.8, 0.3}, {0.3, 0.3, 0.3}, 20)

local scene = gr.node('root')

-- The checkerboard: 20 x 18 unit tiles from z = 4 back to z = -14.
for i = -10, 9 do
  for k = -14, 3 do
    local tile = gr.cube('tile')
    tile:scale(1, 0.2, 1)
    tile:translate(i, -1.2, k)
    tile:set_material((i + k) % 2 == 0 and white or black)
    scene:add_child(tile)
  end
end

-- A wall far behind.
local wall = gr.cube('wall')
wall:scale(60, 30, 1)
wall:translate(-30, -1.2, -15)
wall:set_material(wallM)
scene:add_child(wall)

local ball = gr.nh_sphere('ball', {-1.3, 0, -3}, 1)
ball:set_material(red)
scene:add_child(ball)
local mirror = gr.nh_sphere('mirror', {1.4, 0, -4.5}, 1)
mirror:set_material(steel)
scene:add_child(mirror)

-- Posts of falling thickness (0.16 down to 0.01 units, about 2 to 0.1 pixels at this
-- distance), and two wires across them.
local widths = {0.16, 0.1, 0.06, 0.04, 0.025, 0.015, 0.01}
for n, w in ipairs(widths) do
  local post = gr.cube('post' .. n)
  post:scale(w, 3.5, w)
  post:translate(-4.2 + 1.3 * n, -1, -9)
  post:set_material(postM)
  scene:add_child(post)
end
for n, h in ipairs({0.03, 0.012}) do
  local wire = gr.cube('wire' .. n)
  wire:scale(9.5, h, h)
  wire:translate(-3.5, 1.4 + 0.6 * n, -9)
  wire:set_material(postM)
  scene:add_child(wire)
end

local sun = gr.light({-6, 9, 6}, {0.85, 0.85, 0.8}, {1, 0, 0})
local fill = gr.light({5, 4, 3}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'chapter08-antialiasing.png', 256, 192,
          {0, 1.3, 4}, {0, -0.25, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {sun, fill})
