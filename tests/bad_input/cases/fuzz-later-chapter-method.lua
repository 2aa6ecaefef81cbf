-- skip-if-feature: csg
-- Found by fuzzing (tests/fuzz/regressions/lua_scene/leak-later-chapter-call.lua): the error
-- for a call of a chapter this build lacks leaked its message strings. The message must still
-- name the method, its chapter and the line.
-- expect: method 'csg' needs chapter 14 (csg)
-- expect: build it with make chapter14 or later
local a = gr.sphere('a')
a:csg(gr.sphere('b'), 'u') --!
