-- needs-feature: photon_map
-- A negative gather radius.
-- expect: gr.photons: field 'radius' must be a number from
gr.photons{radius = -0.1} --!
local s = gr.sphere('s')
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1))
gr.render(s, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.1, 0.1, 0.1}, {gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})})
