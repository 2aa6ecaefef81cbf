-- A vertex normal written as nan: chapter 9 would interpolate it, so the reader refuses it.
-- expect: nan-normal.obj:5: 'nan' is not a finite number
local m = gr.mesh('m', 'objs/nan-normal.obj') --!
