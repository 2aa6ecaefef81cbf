-- 0/0 is NaN in Lua; a NaN in a position tuple.
-- expect: gr.nh_sphere: argument 2 (centre) must be a table of 3 numbers, but element 1 is nan
local s = gr.nh_sphere('s', {0/0, 0, 0}, 1) --!
