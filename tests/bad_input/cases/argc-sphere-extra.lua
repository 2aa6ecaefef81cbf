-- gr.sphere with a centre and radius, as if it were nh_sphere.
-- expect: gr.sphere expects 1 argument (name), got 3
local s = gr.sphere('s', {0, 0, 0}, 1) --!
