-- A vertex with two coordinates.
-- expect: short-vertex.obj:2: expected 3 numbers after 'v', got 2
local m = gr.mesh('m', 'objs/short-vertex.obj') --!
