-- A mesh path that is a folder.
-- expect: cannot open OBJ file (Is a directory)
local m = gr.mesh('m', 'objs') --!
