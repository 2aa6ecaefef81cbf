-- needs-feature: photon_map
-- Alpha 1 never shrinks the radius (that is method = 'classic').
-- expect: gr.photons: field 'alpha' must lie strictly between 0 and 1
gr.photons{alpha = 1} --!
local s = gr.sphere('s')
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1))
gr.render(s, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.1, 0.1, 0.1}, {gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})})
