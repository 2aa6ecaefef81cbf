-- -math.huge as a shininess.
-- expect: gr.material: argument 3 (shininess) must be finite, got inf
local m = gr.material({1, 1, 1}, {1, 1, 1}, -math.huge) --!
