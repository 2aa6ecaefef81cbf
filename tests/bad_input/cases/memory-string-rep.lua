-- A 3 GiB string: refused by the default memory limit for scripts (2 GiB) when Lua asks for it,
-- before a byte of it is written.
-- expect: exceeded the memory limit of 2.0 GiB for scripts
local s = string.rep('a', 3 << 30) --!
