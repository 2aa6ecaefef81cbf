-- needs-feature: bump
-- Ripples need a positive wavelength.
-- expect: material:set_bump: field 'wavelength' must be positive
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump{pattern = 'ripples', strength = 0.01, wavelength = 0} --!
