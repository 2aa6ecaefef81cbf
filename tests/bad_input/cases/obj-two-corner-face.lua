-- A face with two corners.
-- expect: two-corner-face.obj:4: a face needs at least 3 corners, got 2
local m = gr.mesh('m', 'objs/two-corner-face.obj') --!
