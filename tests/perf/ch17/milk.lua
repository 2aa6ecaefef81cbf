-- Chapter 17's dense medium (issue 36; tests/perf/ch17/milk_convergence.sh): a ball of a
-- milk-like medium beside a white diffuse ball, under one point light.
--   milk: unit sphere at (-1.1, 0, 0), sigma_s 45, sigma_a 0.05 per unit, isotropic, no surface
--   (its light is almost all multiply scattered: a path scatters hundreds of times);
--   white ball: unit sphere at (1.1, 0, 0), kd 0.8;
--   one point light without falloff at (2, 4, 5), intensity 1; ambient 0.1; black background;
--   16 jittered samples a pixel, multiple scattering on (no cap on the walk, the default).
gr.antialias{sampler = 'jittered', samples = 16}
local root = gr.node('root')

local milk = gr.sphere('milk')
milk:translate(-1.1, 0, 0)
milk:set_medium(gr.medium{sigma_s = 45, sigma_a = 0.05})
root:add_child(milk)

local white = gr.sphere('white')
white:translate(1.1, 0, 0)
white:set_material(gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1))
root:add_child(white)

local light = gr.light({2, 4, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'ch17-milk.png', 96, 64, {0, 0, 6}, {0, 0, -1}, {0, 1, 0}, 45,
          {0.1, 0.1, 0.1}, {light})
