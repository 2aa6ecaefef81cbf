-- gr.nh_box with separate width, height and depth.
-- expect: gr.nh_box expects 3 arguments
local b = gr.nh_box('b', {0, 0, 0}, 1, 2, 3) --!
