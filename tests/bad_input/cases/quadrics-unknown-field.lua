-- A field gr.cone does not know (a typo of top_radius): "gr.cone: unknown field 'topradius'
-- (known: name, open, top_radius)" with chapter 15, "gr.cone needs chapter 15" without it
-- (the chapter-3 suite runs every case). tests/ch15_quadrics.cpp checks the full message.
-- expect: gr.cone
local k = gr.cone{name = 'k', topradius = 0.5} --!
