-- node:translate with two coordinates.
-- expect: node:translate expects 3 arguments (x, y, z), got 2
local n = gr.node('n')
n:translate(1, 2) --!
