-- An unclosed function: Lua reports it at the end of the file (which has no final newline).
-- expect: 'end' expected (to close 'function' at line 3)
local function f()
  return 1
--!