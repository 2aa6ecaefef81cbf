-- OBJ indices start at 1.
-- expect: index-zero.obj:4: face index 0 is invalid
local m = gr.mesh('m', 'objs/index-zero.obj') --!
