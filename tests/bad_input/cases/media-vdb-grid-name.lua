-- needs-feature: media
-- The plume holds one grid, 'density'; asking for another names the ones it has.
-- expect: density
-- expect: temperature
local m = gr.medium{density = {file = '../../../scenes/assets/plume.nvdb', grid = 'temperature'}} --!
