-- A vertex coordinate written as inf.
-- expect: inf-vertex.obj:3: 'inf' is not a finite number
local m = gr.mesh('m', 'objs/inf-vertex.obj') --!
