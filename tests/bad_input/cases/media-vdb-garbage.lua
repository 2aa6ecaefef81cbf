-- needs-feature: media
-- A file that is not a NanoVDB grid at all.
-- expect: garbage.nvdb
local m = gr.medium{density = {file = 'grids/garbage.nvdb'}} --!
