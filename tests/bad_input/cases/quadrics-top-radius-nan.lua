-- A frustum's top radius that is not a number from 0 to 1.
-- expect: gr.cone: field 'top_radius' must be a number from 0 (a pointed cone) to 1
local k = gr.cone{top_radius = 0/0} --!
