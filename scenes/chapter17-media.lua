-- Chapter 17: participating media. A room in the course's style (white floor, ceiling and
-- walls, a red wall on the left, a green one on the right), closed all round, with a window in
-- the left wall and the sun outside it. Thin fog fills the room, so the window's
-- light draws a shaft across the room; a plume of smoke from a NanoVDB grid
-- (assets/plume.nvdb, made by rb_make_plume) rises from the floor into the shaft, bright where
-- the sun strikes it and shadowing the floor behind it. The camera stands inside the fog.
gr.antialias{sampler = 'jittered', samples = 144}
gr.option('max_depth', 4)

local white = gr.material{kd = {0.75, 0.75, 0.72}, ks = {0, 0, 0}, shininess = 1}
local red   = gr.material{kd = {0.70, 0.14, 0.12}, ks = {0, 0, 0}, shininess = 1}
local green = gr.material{kd = {0.16, 0.55, 0.17}, ks = {0, 0, 0}, shininess = 1}

local root = gr.node('root')

-- The room: x in [-1, 1], y in [0, 2], z in [-1, 2]; each wall a unit cube scaled thin.
local function wall(name, material, sx, sy, sz, x, y, z)
  local w = gr.cube(name)
  w:scale(sx, sy, sz)
  w:translate(x, y, z)
  w:set_material(material)
  root:add_child(w)
end
wall('floor',   white, 2.2, 0.1, 3.2, -1.1, -0.1, -1.1)
wall('ceiling', white, 2.2, 0.1, 3.2, -1.1,  2.0, -1.1)
wall('back',    white, 2.2, 2.2, 0.1, -1.1, -0.1, -1.1)
wall('front',   white, 2.2, 2.2, 0.1, -1.1, -0.1,  2.0)
wall('right',   green, 0.1, 2.2, 3.2,  1.0, -0.1, -1.1)
-- The left wall, around a window 0.7 tall and 0.5 wide (y in [1.0, 1.7], z in [-0.35, 0.15]).
wall('left below',  red, 0.1, 1.1, 3.2, -1.1, -0.1, -1.1)
wall('left above',  red, 0.1, 0.4, 3.2, -1.1,  1.7, -1.1)
wall('left behind', red, 0.1, 0.7, 0.75, -1.1, 1.0, -1.1)
wall('left front',  red, 0.1, 0.7, 1.85, -1.1, 1.0,  0.15)

-- Thin, slightly forward-scattering fog fills the room: a cube without a material of its own
-- only bounds its medium. (gr.fog would fill the sky outside too, and dim the sun.)
local air = gr.cube('fog')
air:scale(2, 2, 3)
air:translate(-1, 0, -1)
air:set_medium(gr.medium{sigma_s = 0.3, sigma_a = 0.02, g = 0.4})
root:add_child(air)

-- The smoke: a group node holds a grid in the box of its voxels (1 x 2 x 1, standing on y = 0).
local smoke = gr.node('smoke')
smoke:set_medium(gr.medium{sigma_s = 30, sigma_a = 3, g = 0.2,
                           density = {file = 'assets/plume.nvdb', grid = 'density'}})
smoke:scale(0.8, 0.8, 0.8)
smoke:translate(-0.3, 0.0, -0.1)
root:add_child(smoke)

-- The sun: far off beyond the window, without falloff.
local sun = gr.light({-6, 5.2, -0.35}, {3.0, 2.8, 2.4}, {1, 0, 0})
-- A dim lamp under the ceiling, behind the camera: the smoke outside the shaft takes shape.
local lamp = gr.light({0.3, 1.85, 1.6}, {0.35, 0.33, 0.3}, {1, 0, 0})
gr.render(root, 'chapter17-media.png', 192, 144,
          {0, 1.0, 1.95}, {0, -0.12, -1}, {0, 1, 0}, 62,
          {0.08, 0.08, 0.08}, {sun, lamp})
