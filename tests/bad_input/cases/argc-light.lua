-- gr.light without its falloff.
-- expect: gr.light expects 3 arguments
local l = gr.light({0, 0, 5}, {1, 1, 1}) --!
