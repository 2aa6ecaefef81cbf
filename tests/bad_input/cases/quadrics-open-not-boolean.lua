-- open must be true or false, not a number: "gr.cylinder: field 'open' must be true or false"
-- with chapter 15, "gr.cylinder needs chapter 15" without it.
-- tests/ch15_quadrics.cpp checks the full message.
-- expect: gr.cylinder
local c = gr.cylinder{open = 1} --!
