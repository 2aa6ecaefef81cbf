-- batch-expect: ok
-- Handed in late, with a space and an ampersand in its name: two renders, a day view and a
-- night view of the same moon over a sea.
local root = gr.node('root')
local sea = gr.cube('sea')
sea:scale(40, 1, 40)
sea:translate(-20, -1, -35)
sea:set_material(gr.material({0.1, 0.25, 0.5}, {0.6, 0.6, 0.6}, 80))
root:add_child(sea)
local moon = gr.nh_sphere('moon', {2, 3, -15}, 1.5)
moon:set_material(gr.material({0.9, 0.9, 0.8}, {0.1, 0.1, 0.1}, 5))
root:add_child(moon)
local sun = gr.light({-5, 10, 5}, {1, 0.95, 0.8}, {1, 0, 0})
local glow = gr.light({0, 2, 2}, {0.25, 0.25, 0.4}, {1, 0, 0})
gr.render(root, 'day.png', 120, 80, {0, 1, 5}, {0, 0.05, -1}, {0, 1, 0}, 50,
          {0.5, 0.55, 0.6}, {sun})
gr.render(root, 'night.png', 120, 80, {0, 1, 5}, {0, 0.05, -1}, {0, 1, 0}, 50,
          {0.05, 0.05, 0.1}, {glow})
