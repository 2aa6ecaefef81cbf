-- A string where a number should be.
-- expect: node:translate: argument 2 (x) must be a number, got string
local n = gr.node('n')
n:translate('1', 0, 0) --!
