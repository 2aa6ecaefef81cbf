-- A number where the name should be.
-- expect: gr.sphere: argument 1 (name) must be a string, got number
local s = gr.sphere(42) --!
