-- A string that doubles without bound must stop at the memory limit.
-- expect: exceeded the memory limit
local s = 'x'
while true do s = s .. s end
