-- Found while fixing fuzzing's leaks (tests/fuzz/regressions/lua_scene/
-- leak-area-light-index-metamethod.lua): gr.area_light{...} read its fields through the
-- table's __index, whose error leaked the reader's strings. Fields are read raw now, so the
-- metamethod never runs: the field is missing (chapter 6 and later), or the call needs
-- chapter 6 (chapter 3's binary).
-- expect: gr.area_light
-- reject: no field
local t = setmetatable({}, {__index = function(_, k) error('no field ' .. k) end})
local l = gr.area_light(t) --!
