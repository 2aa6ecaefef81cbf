-- Found by fuzzing's first finding, on review (tests/fuzz/regressions/lua_scene/
-- leak-require-missing.lua): require of a missing module with a long name leaked the name and
-- the exception. The message must still name the module, the scene file and the line.
-- expect: require('a_module_name_longer_than_fifteen_characters')
-- expect: cannot find 'a_module_name_longer_than_fifteen_characters.lua'
require('a_module_name_longer_than_fifteen_characters') --!
