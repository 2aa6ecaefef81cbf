-- A relative index that reaches before the first vertex.
-- expect: negative-out-of-range.obj:4: face index -4 is out of range
local m = gr.mesh('m', 'objs/negative-out-of-range.obj') --!
