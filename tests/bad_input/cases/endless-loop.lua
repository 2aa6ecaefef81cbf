-- A script that never ends must stop at the instruction limit, naming the file and line.
-- expect: Lua instructions
local i = 0
while true do i = i + 1 end --!
