-- A four-element colour.
-- expect: gr.material: argument 1 (kd) must be a table of 3 numbers, got a table of 4
local m = gr.material({1, 0, 0, 1}, {0, 0, 0}, 10) --!
