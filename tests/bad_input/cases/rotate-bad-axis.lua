-- A rotation about an axis that does not exist.
-- expect: node:rotate: the axis must be 'x', 'y' or 'z', got 'w'
local n = gr.node('n')
n:rotate('w', 30) --!
