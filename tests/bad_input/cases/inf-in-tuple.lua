-- 1/0 is +Inf in Lua; an Inf in a light colour.
-- expect: gr.light: argument 2 (colour) must be a table of 3 numbers, but element 3 is inf
local l = gr.light({0, 0, 5}, {1, 1, 1/0}, {1, 0, 0}) --!
