-- needs-feature: path_tracing
-- NaN emission would put NaN pixels in every picture the surface lights: refused.
-- expect: gr.material: field 'emission'
local lamp = gr.material{kd = {0, 0, 0}, emission = {1, 0/0, 1}} --!
