-- Chapter 12: tone mapping. A dark room with one window. Outside, a sun (a point light 400 times
-- brighter than the lamp indoors) lights a wall of sky and throws a patch of sunlight through
-- the window onto the floor; inside, only a dim lamp and a little ambient light reach the
-- corners. The film spans over twenty thousand to one, from 0.008 in the corners to 180 on the floor:
-- clipped (--tone-map=none) the window and the sunlit floor burn out to flat white and the
-- room is black; Reinhard's global operator (--tone-map=global) keeps both ends but flattens the
-- middle; the local operator (the scene's choice) dodges the dark corners and burns the window
-- so that the wall beside it, the sky's gradient and the shapes in the shade all stay readable.
-- Compare: --tone-map=none, --tone-map=global, --exposure=2, --output room.hdr (the film).
gr.tone_map{operator = 'local', key = 0.18}

local plaster = gr.material({0.7, 0.68, 0.62}, {0, 0, 0}, 1)
local floorM  = gr.material({0.55, 0.42, 0.3}, {0.2, 0.2, 0.2}, 20)
local skyM    = gr.material({0.55, 0.7, 0.95}, {0, 0, 0}, 1)
local groundM = gr.material({0.35, 0.5, 0.25}, {0, 0, 0}, 1)
local red     = gr.material({0.8, 0.12, 0.1}, {0.5, 0.5, 0.5}, 40)
local blue    = gr.material({0.15, 0.25, 0.7}, {0.4, 0.4, 0.4}, 30)
local white   = gr.material({0.85, 0.85, 0.85}, {0.6, 0.6, 0.6}, 60)

local scene = gr.node('root')

--- A box with its minimum corner at (x, y, z) and sides (w, h, d).
local function box(name, x, y, z, w, h, d, m)
  local b = gr.cube(name)
  b:scale(w, h, d)
  b:translate(x, y, z)
  b:set_material(m)
  scene:add_child(b)
end

-- The room: x in [-4, 4], y in [0, 5], z in [-6, 2]; the back wall has a window
-- x in [-1.5, 1.5], y in [1.5, 4].
-- The floor is boards of two slightly different woods: a 10% contrast, the kind of detail a
-- tone map must keep in the sunlit patch.
local floorB = gr.material({0.5, 0.38, 0.27}, {0.2, 0.2, 0.2}, 20)
for i = 0, 15 do
  box('board' .. i, -4 + 0.5 * i, -0.2, -6, 0.5, 0.2, 8, i % 2 == 0 and floorM or floorB)
end
box('ceiling', -4, 5, -6, 8, 0.2, 8, plaster)
box('left', -4.2, 0, -6, 0.2, 5, 8, plaster)
box('right', 4, 0, -6, 0.2, 5, 8, plaster)
box('behind', -4, 0, 2, 8, 5, 0.2, plaster)
box('wall-below', -4, 0, -6.2, 8, 1.5, 0.2, plaster)
box('wall-above', -4, 4, -6.2, 8, 1, 0.2, plaster)
box('wall-left', -4, 1.5, -6.2, 2.5, 2.5, 0.2, plaster)
box('wall-right', 1.5, 1.5, -6.2, 2.5, 2.5, 0.2, plaster)
-- A window bar across the opening.
box('bar', -1.5, 2.7, -6.15, 3, 0.1, 0.1, plaster)

-- Outside: the ground and a wall of sky, lit by the sun in front of it.
box('ground', -30, -0.4, -20, 60, 0.2, 14, groundM)
box('sky', -30, -0.4, -21, 60, 30, 0.5, skyM)
local tree = gr.nh_sphere('tree', {-2.2, 2.2, -16}, 1.6)
tree:set_material(groundM)
scene:add_child(tree)
box('house', 1.2, -0.2, -17, 2.6, 2.4, 2, red)

-- Inside: a ball in the sunlit patch, and shapes in the shade.
local sunBall = gr.nh_sphere('sun-ball', {0.9, 0.7, -2.2}, 0.7)
sunBall:set_material(white)
scene:add_child(sunBall)
local shadeBall = gr.nh_sphere('shade-ball', {-2.6, 0.9, -3.8}, 0.9)
shadeBall:set_material(red)
scene:add_child(shadeBall)
box('shade-box', 2.2, 0, -4.6, 1.3, 1.3, 1.3, blue)

local sun = gr.light({0, 9, -14}, {200, 190, 165}, {1, 0, 0})
local lamp = gr.light({-3, 4.5, 1}, {0.5, 0.45, 0.35}, {1, 0, 0.02})

gr.render(scene, 'chapter12-tone-mapping.png', 192, 144,
          {0, 2.4, 1.7}, {0, -0.12, -1}, {0, 1, 0}, 62,
          {0.03, 0.03, 0.035}, {sun, lamp})
