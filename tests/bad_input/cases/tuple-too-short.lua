-- A tuple of the wrong length: the message names the call and the argument.
-- expect: gr.nh_sphere: argument 2 (centre) must be a table of 3 numbers, got a table of 2
local s = gr.nh_sphere('s', {0, 0}, 1) --!
