-- Seed 001's form takes a name.
-- expect: gr.cyllinder: argument 1 (name) must be a string
local c = gr.cyllinder(42) --!
