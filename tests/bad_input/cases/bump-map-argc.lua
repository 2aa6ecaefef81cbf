-- needs-feature: bump
-- set_bump_map takes one file name.
-- expect: material:set_bump_map expects 1 argument (file), got 0
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump_map() --!
