-- A file with vertices but no faces.
-- expect: no-faces.obj: has no faces
local m = gr.mesh('m', 'objs/no-faces.obj') --!
