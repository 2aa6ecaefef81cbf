-- A falloff of {0,0,0} would divide by zero.
-- expect: gr.light: argument 3 (falloff) must be non-negative and not all zero
local l = gr.light({0, 0, 5}, {1, 1, 1}, {0, 0, 0}) --!
