-- A NaN radius.
-- expect: gr.nh_sphere: argument 3 (radius) must be finite, got nan
local s = gr.nh_sphere('s', {0, 0, 0}, 0/0) --!
