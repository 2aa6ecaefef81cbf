-- Chapter 18: path tracing. The Cornell box as its makers measured it (Cornell University
-- Program of Computer Graphics, www.graphics.cornell.edu/online/box/data.html), in units of
-- 100 mm, lit only by the lamp in its ceiling: every wall is lit by the light the others
-- reflect, the red and green walls bleed their colour onto the blocks, and the blocks' shadows
-- are soft because the lamp has an area. No A4 light and no ambient term: the path tracer
-- computes all of the indirect light.
gr.integrator{method = 'path', max_depth = 64}
gr.antialias{sampler = 'jittered', samples = 64}
gr.tone_map{operator = 'none', srgb = true}

-- The box's reflectances, averaged over each colour's band of its measured spectra.
local white = gr.material{kd = {0.725, 0.71, 0.68}}
local red   = gr.material{kd = {0.63, 0.065, 0.05}}
local green = gr.material{kd = {0.14, 0.45, 0.091}}
-- The lamp: 130 x 105 mm, radiance (17, 12, 4) as in the data's own renderings.
local lamp  = gr.material{kd = {0.78, 0.78, 0.78}, emission = {17, 12, 4}}

local root = gr.node('root')

-- Each wall is a unit cube scaled thin, outside the box's inside: x in [0, 5.56],
-- y in [0, 5.488], z in [0, 5.592]. The front is open; the camera stands outside it.
local function slab(name, material, sx, sy, sz, x, y, z)
  local s = gr.cube(name)
  s:scale(sx, sy, sz)
  s:translate(x, y, z)
  s:set_material(material)
  root:add_child(s)
end
slab('floor',   white, 5.76, 0.1, 5.692, -0.1, -0.1,   0)
slab('ceiling', white, 5.76, 0.1, 5.692, -0.1, 5.488,  0)
slab('back',    white, 5.76, 5.688, 0.1, -0.1, -0.1, 5.592)
slab('left',    red,   0.1, 5.688, 5.692, 5.56, -0.1,  0)
slab('right',   green, 0.1, 5.688, 5.692, -0.1, -0.1,  0)
-- The lamp is set into the ceiling, its face 0.01 mm below it: only that face shows (a lamp
-- hanging below the ceiling would light the gap above it, and its sides the ceiling beside
-- it, brightly enough to throw speckles all over the room).
slab('lamp',    lamp,  1.30, 0.0002, 1.05, 2.13, 5.4879, 2.27)

-- The two blocks, white, each turned about its own vertical axis.
local function block(name, height, degrees, x, z)
  local b = gr.cube(name)
  b:translate(-0.5, 0, -0.5)
  b:scale(1.65, height, 1.65)
  b:rotate('y', degrees)
  b:translate(x, 0, z)
  b:set_material(white)
  root:add_child(b)
end
block('short', 1.65, -17, 1.855, 1.69)
block('tall',  3.30,  17, 3.685, 3.5125)

gr.render(root, 'chapter18-path-tracing.png', 160, 160,
          {2.78, 2.73, -8.0}, {0, 0, 1}, {0, 1, 0}, 39.3,
          {0, 0, 0}, {})
