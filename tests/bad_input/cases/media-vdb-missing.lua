-- needs-feature: media
-- A grid file that is not there: the call and the places searched.
-- expect: no-such-plume.nvdb
local m = gr.medium{density = {file = 'no-such-plume.nvdb'}} --!
