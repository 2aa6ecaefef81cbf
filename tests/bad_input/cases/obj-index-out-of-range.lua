-- A face that names vertex 9 of 4; the message names the OBJ file and its line.
-- expect: index-out-of-range.obj:7: face index 9 is out of range (the file has 4 vertices so far)
local m = gr.mesh('m', 'objs/index-out-of-range.obj') --!
