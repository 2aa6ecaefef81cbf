-- A mesh file that does not exist (neither beside the working directory nor the scene).
-- expect: no-such-mesh.obj: cannot open OBJ file (No such file or directory)
local m = gr.mesh('m', 'no-such-mesh.obj') --!
