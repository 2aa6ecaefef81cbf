-- A frustum's top radius that is NaN: "gr.cone: field 'top_radius' must be a number from 0 (a
-- pointed cone) to 1" with chapter 15, "gr.cone needs chapter 15" without it.
-- tests/ch15_quadrics.cpp checks the full message.
-- expect: gr.cone
local k = gr.cone{top_radius = 0/0} --!
