-- A scale by 0 makes the transform singular.
-- expect: node:scale: scale factors must be non-zero
local n = gr.sphere('n')
n:scale(1, 0, 1) --!
