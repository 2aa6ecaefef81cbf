-- needs-feature: media
-- rt-args: --media-direct=equi
-- An unknown single-scattering method is refused with the three it may be.
-- expect: --media-direct: expected 'mis', 'flight' or 'light', got 'equi'
local fog = gr.cube('fog')
fog:set_medium(gr.medium{sigma_s = 0.3})
gr.render(fog, 'x.png', 8, 8, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},
          {gr.light({1, 2, 3}, {1, 1, 1}, {1, 0, 0})})
