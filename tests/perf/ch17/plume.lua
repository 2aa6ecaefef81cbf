-- Chapter 17's speed-accuracy scene (tests/perf/ch17/charts.sh): the chapter's VDB plume
-- (scenes/assets/plume.nvdb, density 0 to 1 in a 1 x 2 x 1 box) in a group node, on a grey
-- floor, lit by one point light without falloff. Run with --media-bounces=0 (single
-- scattering), so ray marching, delta tracking and ratio tracking estimate the same image.
-- Paths are from the repository root, where the charts run ./rt.
gr.antialias{sampler = 'jittered', samples = 1}  -- --spp N sets the samples

local grey = gr.material{kd = {0.2, 0.2, 0.2}, ks = {0, 0, 0}, shininess = 1}
local root = gr.node('root')
local floor = gr.cube('floor')
floor:scale(4, 0.1, 4)
floor:translate(-2, -0.1, -2)
floor:set_material(grey)
root:add_child(floor)

local smoke = gr.node('smoke')
smoke:set_medium(gr.medium{sigma_s = 30, sigma_a = 3, g = 0.2,
                           density = {file = 'scenes/assets/plume.nvdb', grid = 'density'}})
smoke:scale(1.1, 1.1, 1.1)
smoke:translate(0.1, 0.0, -0.3)
root:add_child(smoke)

local light = gr.light({-1.5, 2.6, 1.2}, {4, 4, 3.8}, {1, 0, 0})
gr.render(root, 'ch17-plume.png', 96, 96, {0, 1.1, 2.7}, {0, -0.08, -1}, {0, 1, 0}, 50,
          {0.05, 0.05, 0.08}, {light})
