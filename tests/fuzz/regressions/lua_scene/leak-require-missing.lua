-- Found reviewing the first finding (the same pattern): require of a missing module raised
-- luaL_error inside a catch block, leaking the exception and the module's long name.
require('a_module_name_longer_than_fifteen_characters')
