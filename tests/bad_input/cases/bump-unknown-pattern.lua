-- needs-feature: bump
-- A bump pattern that does not exist.
-- expect: material:set_bump: unknown pattern 'waves' (expected 'ripples', 'noise', 'ramp' or 'image')
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump{pattern = 'waves', strength = 1} --!
