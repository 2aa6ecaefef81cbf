-- An infinite translation.
-- expect: node:translate: argument 3 (y) must be finite, got inf
local n = gr.node('n')
n:translate(0, 1/0, 0) --!
