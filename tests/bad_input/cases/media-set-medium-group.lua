-- needs-feature: media
-- A group node has no closed shape to fill, and a constant medium has no box of its own.
-- expect: has no shape
local n = gr.node('n')
n:set_medium(gr.medium{sigma_s = 1}) --!
