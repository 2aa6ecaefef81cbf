-- Found by review while fixing the fuzzer's leaks, confirmed with fuzz_lua_scene (LeakSanitizer):
-- gr.area_light{...} read its named fields with lua_getfield, which runs the table's __index;
-- an __index that raised an error longjmped over the reader's C++ strings. Fields are now read
-- raw, as tuples always were.
local t = setmetatable({}, {__index = function(_, k) error('no field ' .. k) end})
local l = gr.area_light(t)
