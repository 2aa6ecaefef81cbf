-- A vertex with a word where a number should be.
-- expect: malformed-number.obj:3: 'abc' is not a number
local m = gr.mesh('m', 'objs/malformed-number.obj') --!
