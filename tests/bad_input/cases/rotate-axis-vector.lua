-- A rotation axis given as a vector.
-- expect: node:rotate: argument 2 (axis) must be a string, got table
local n = gr.node('n')
n:rotate({0, 1, 0}, 30) --!
