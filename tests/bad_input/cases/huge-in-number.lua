-- math.huge as a scale factor.
-- expect: node:scale: argument 2 (x) must be finite, got inf
local n = gr.node('n')
n:scale(math.huge, 1, 1) --!
