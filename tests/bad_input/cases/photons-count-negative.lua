-- needs-feature: photon_map
-- A negative photon count.
-- expect: gr.photons: field 'count' must be a whole number from 1
gr.photons{count = -20000} --!
local s = gr.sphere('s')
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1))
gr.render(s, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.1, 0.1, 0.1}, {gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})})
