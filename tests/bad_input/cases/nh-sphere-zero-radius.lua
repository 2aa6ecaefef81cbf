-- A sphere of radius 0.
-- expect: gr.nh_sphere: argument 3 (radius) must be positive
local s = gr.nh_sphere('s', {0, 0, 0}, 0) --!
