-- Chapter 17's noise majorant, measured alone: seed 000's steam (scenes/seeds/000-bathhouse.lua,
-- chapter 11's noise of frequency 2.2, 3 octaves, bias 0.05, gain 1.2, in a 4.2 x 1.4 x 3.4 box)
-- before a grey wall, lit by one point light, 100 jittered samples per pixel, single scattering.
-- Compare the default 16^3 majorant grid with one flat cell (the bound the smoke had before):
--   for m in 1 16; do ./rt --stats --threads 1 --media-majorant $m tests/perf/ch17/steam.lua; done
gr.antialias{sampler = 'jittered', samples = 100}
gr.option('media_bounces', 0)
local grey = gr.material{kd = {0.5, 0.5, 0.5}, ks = {0, 0, 0}, shininess = 1}
local root = gr.node('root')
local wall = gr.cube('wall'); wall:scale(10, 6, 0.1); wall:translate(-5, -1, -6); wall:set_material(grey); root:add_child(wall)
local steam = gr.cube('steam')
steam:scale(4.2, 1.4, 3.4)
steam:translate(-2.1, -0.7, -3.4)
steam:set_medium(gr.medium{sigma_s = 3, sigma_a = 0.05, g = 0.3,
                           density = {noise = 2.2, octaves = 3, bias = 0.05, gain = 1.2, seed = 7}})
root:add_child(steam)
local light = gr.light({2, 4, 3}, {0.9, 0.9, 0.9}, {1, 0, 0})
gr.render(root, 'ch17-steam.png', 160, 120, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light})
