-- A box of negative size.
-- expect: gr.nh_box: argument 3 (size) must be positive
local b = gr.nh_box('b', {0, 0, 0}, -1) --!
