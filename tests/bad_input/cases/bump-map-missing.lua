-- needs-feature: bump
-- Seed 002's height map, but the image is not there: every place searched is named.
-- expect: material:set_bump_map: cannot find 'no-such-bumps.png'; looked in:
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump_map('no-such-bumps.png') --!
