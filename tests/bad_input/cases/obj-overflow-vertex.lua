-- A vertex coordinate too large for a double.
-- expect: overflow-vertex.obj:1: '1e999' is not a finite number
local m = gr.mesh('m', 'objs/overflow-vertex.obj') --!
