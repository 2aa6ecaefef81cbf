-- needs-feature: media
-- rt-args: --media-points=0
-- No lamp points at all would leave single scattering to --media-direct=flight: refused, with
-- the range.
-- expect: --media-points: expected a whole number from 1 to 1024, got 0
local fog = gr.cube('fog')
fog:set_medium(gr.medium{sigma_s = 0.3})
gr.render(fog, 'x.png', 8, 8, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},
          {gr.light({1, 2, 3}, {1, 1, 1}, {1, 0, 0})})
