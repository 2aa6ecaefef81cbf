-- node:rotate with an axis vector instead of an axis name.
-- expect: node:rotate expects 2 arguments (axis, degrees)
local n = gr.node('n')
n:rotate(0, 1, 0, 45) --!
