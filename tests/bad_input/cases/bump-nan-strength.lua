-- needs-feature: bump
-- A NaN bump strength.
-- expect: material:set_bump: field 'strength' must be finite, got nan
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump{pattern = 'noise', strength = 0/0} --!
