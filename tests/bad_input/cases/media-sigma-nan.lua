-- needs-feature: media
-- expect: sigma_a
local m = gr.medium{sigma_a = 0/0} --!
