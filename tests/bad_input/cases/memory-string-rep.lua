-- A string of 2 GiB less 4 KiB (Lua's largest is 2 GiB): with what the script already holds it
-- passes the default memory limit for scripts (2 GiB), and is refused when Lua asks for it,
-- before a byte of it is written.
-- expect: exceeded the memory limit of 2.0 GiB for scripts
local s = string.rep('a', (1 << 31) - 4096)
