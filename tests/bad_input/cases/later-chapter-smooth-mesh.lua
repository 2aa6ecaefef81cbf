-- skip-if-feature: smooth_mesh
-- gr.smooth_mesh belongs to chapter 9: a build without it names the chapter.
-- expect: gr.smooth_mesh needs chapter 9 (smooth_mesh)
local m = gr.smooth_mesh('m', 'objs/nan-normal.obj') --!
