-- Found by fuzz_lua_scene (LeakSanitizer): the error for a call of a chapter this build lacks
-- was raised with luaL_error while the C++ strings of its message were alive; luaL_error
-- longjmps over their destructors, so each such error leaked them.
local c = gr.cone('c')
