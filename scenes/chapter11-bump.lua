-- Chapter 11: bump mapping. Every surface here is geometrically smooth: a flat pond, two
-- spheres, a block and flat walls. Only their shading normals are bumped. The pond has ripples
-- from two drops (material:set_bump with pattern 'ripples') and reflects the scene through
-- them. The orange ball is rough, with four octaves of gradient noise. The steel ball is
-- hammered, with coarser noise on a mirror. The block's tiles come from a height map (seed
-- 002's set_bump_map). Look at the silhouettes: they stay perfectly round and straight,
-- because a bump moves no geometry (the method's known limit). Compare: --features=all,-bump
-- renders the same scene unbumped.
gr.antialias{sampler = 'jittered', samples = 4}

-- Height fields live in each object's own space. The pond is the unit cube scaled by 12, so
-- its ripples have a wavelength of 0.025 * 12 = 0.3 world units, and strength 0.0008 * 12
-- lifts each crest by 0.0096: slopes up to 2 pi 0.0008 / 0.025 = 0.2.
local water = gr.material{kd = {0.02, 0.06, 0.09}, ks = {0.9, 0.9, 0.9}, shininess = 200,
                          reflect = 0.55}
water:set_bump{pattern = 'ripples', strength = 0.0008, wavelength = 0.025,
               centres = {{0.42, 1, 0.78}, {0.62, 1, 0.55}}}
local pond = gr.nh_box('pond', {-6, -13, -10}, 12)
pond:set_material(water)

-- The balls are unit spheres scaled by 0.9, so the noise cell is 0.2 object units.
local peel = gr.material({0.85, 0.42, 0.08}, {0.5, 0.5, 0.5}, 60)
peel:set_bump{pattern = 'noise', strength = 0.02, scale = 0.15, octaves = 4, seed = 1}
local orange = gr.nh_sphere('orange', {-1.3, -0.2, -4.2}, 0.9)
orange:set_material(peel)

local steel = gr.material{kd = {0.08, 0.08, 0.09}, ks = {0.8, 0.8, 0.8}, shininess = 120,
                          reflect = 0.75}
steel:set_bump{pattern = 'noise', strength = 0.008, scale = 0.25, octaves = 2, seed = 7}
local hammered = gr.nh_sphere('hammered', {1.2, -0.2, -5}, 0.9)
hammered:set_material(steel)

-- A tiled block: seed 002's set_bump_map reads heights from a grey image (tiles 1, grooves 0;
-- made by scenes/assets/tiles-height.py) at the default strength, 0.01 object units per unit of
-- height. The map covers each face once (chapter 10's box-face coordinates).
local stone = gr.material({0.55, 0.6, 0.65}, {0.3, 0.3, 0.3}, 30)
stone:set_bump_map('assets/tiles-height.png')
local block = gr.cube('block')
block:translate(-0.5, 0, -0.5)
block:scale(1.1, 1.1, 1.1)
block:rotate('y', 35)
block:translate(2.6, -0.95, -3.2)
block:set_material(stone)

local plaster = gr.material({0.7, 0.65, 0.55}, {0.05, 0.05, 0.05}, 5)
local wall = gr.cube('wall')
wall:scale(30, 40, 1)
wall:translate(-15, -1.5, -11)
wall:set_material(plaster)
-- The walls are tall, and a second one stands behind the camera, so that every ray the
-- ripples reflect meets a wall rather than the black background.
local back = gr.cube('back')
back:scale(30, 12, 1)
back:translate(-15, -1.5, 6)
back:set_material(plaster)

local scene = gr.node('root')
for _, n in ipairs({pond, orange, hammered, block, wall, back}) do scene:add_child(n) end

local sun = gr.light({-5, 6, 2}, {0.9, 0.88, 0.8}, {1, 0, 0})
local fill = gr.light({6, 3, 1}, {0.25, 0.27, 0.3}, {1, 0, 0})

gr.render(scene, 'chapter11-bump.png', 192, 144,
          {0, 1.1, 2.5}, {0, -0.35, -1}, {0, 1, 0}, 50,
          {0.25, 0.25, 0.28}, {sun, fill})
