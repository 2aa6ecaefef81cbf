-- A tuple element that is a string.
-- expect: element 2 is a string
local b = gr.nh_box('b', {0, '1', 0}, 1) --!
