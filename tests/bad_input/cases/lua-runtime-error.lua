-- A runtime error in the script (indexing nil).
-- expect: attempt to index a nil value
local root = gr.node('root')
local t = nil
t.x = 1 --!
