-- A light whose falloff has two terms.
-- expect: gr.light: argument 3 (falloff) must be a table of 3 numbers
local l = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0}) --!
