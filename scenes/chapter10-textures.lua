-- Chapter 10: textures. Every surface point gets texture coordinates (u, v) and the material's
-- colour is looked up there: a globe on the sphere's angles (u = phi / 2 pi, v = theta / pi;
-- the graticule is drawn every 30 degrees), a crate on the box's faces (the arrow must point
-- up and the red notch right on every face), seed 000's plane.obj standing as a poster (its
-- vt), and a procedural checker floor in the planar mapping running off to the horizon. The
-- images are bilinearly filtered and decoded from sRGB to linear light; this A4-style output
-- writes linear values, so they look darker than the files do (chapter 12 encodes sRGB).
-- Compare --features=all,-texture: the same scene with the materials' own colours.
gr.antialias{sampler = 'jittered', samples = 4}

-- Seed 000's call: the image replaces the material's kd.
local earth = gr.material({0.5, 0.5, 0.5}, {0.25, 0.25, 0.25}, 40)
gr.texture(earth, 'assets/textures/globe.png')

-- raybook's own: a texture object with named fields, put in the material's kd slot.
local wood = gr.material({0.6, 0.4, 0.2}, {0.05, 0.05, 0.05}, 5)
wood:set_texture(gr.texture{image = 'assets/textures/crate.jpg', wrap = 'clamp'})

-- Seed 002's method.
local paper = gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1)
paper:set_texture_map('assets/textures/poster.png')

-- The planar mapping works in the cube's own [0,1] space: scale 60 makes unit squares on the
-- 60-unit floor.
local tiles = gr.material({0.7, 0.7, 0.7}, {0.15, 0.15, 0.15}, 20)
tiles:set_texture(gr.texture{checker = {{0.85, 0.85, 0.8}, {0.12, 0.12, 0.18}},
                             mapping = 'planar', scale = {60, 60}})

local scene = gr.node('root')

local floor = gr.cube('floor')
floor:scale(60, 1, 60)
floor:translate(-30, -2, -50)
floor:set_material(tiles)
scene:add_child(floor)

local globe = gr.sphere('globe')
globe:rotate('y', -60)
globe:rotate('z', 15)
globe:translate(-1.5, 0, -1)
globe:set_material(earth)
scene:add_child(globe)

local crate = gr.cube('crate')
crate:translate(-0.5, 0, -0.5)
crate:scale(1.4, 1.4, 1.4)
crate:rotate('y', 35)
crate:translate(1.5, -0.3, -0.6)
crate:set_material(wood)
scene:add_child(crate)

local poster = gr.mesh('poster', 'assets/textures/plane.obj')
poster:rotate('x', 90)
poster:scale(1.8, 1.2, 1)
poster:translate(0.2, 1.1, -4)
poster:set_material(paper)
scene:add_child(poster)

local sun = gr.light({-4, 8, 6}, {0.9, 0.9, 0.85}, {1, 0, 0})
local fill = gr.light({6, 3, 4}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'chapter10-textures.png', 256, 192,
          {0, 1.2, 5}, {0, -0.25, -1}, {0, 1, 0}, 50,
          {0.35, 0.35, 0.35}, {sun, fill})
