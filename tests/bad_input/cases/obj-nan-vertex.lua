-- A vertex coordinate written as nan (std::from_chars reads it, so it must be refused after).
-- expect: nan-vertex.obj:2: 'nan' is not a finite number
local m = gr.mesh('m', 'objs/nan-vertex.obj') --!
