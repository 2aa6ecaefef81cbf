-- needs-feature: media
-- A negative scattering coefficient would add light from nowhere.
-- expect: field 'sigma_s' must be ≥ 0
local m = gr.medium{sigma_s = {1, -0.5, 1}} --!
