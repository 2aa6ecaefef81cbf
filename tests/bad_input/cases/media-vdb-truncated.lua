-- needs-feature: media
-- The first 4000 bytes of the chapter's plume: refused before anything is read past the end.
-- expect: truncated.nvdb
local m = gr.medium{density = {file = 'grids/truncated.nvdb'}} --!
