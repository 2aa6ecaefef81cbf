-- Seed 001's form takes a name: "gr.cyllinder: argument 1 (name) must be a string" with
-- chapter 15, "gr.cyllinder needs chapter 15" without it.
-- expect: gr.cyllinder
local c = gr.cyllinder(42) --!
