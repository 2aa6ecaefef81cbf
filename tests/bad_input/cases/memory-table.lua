-- A table that grows without bound must stop at the memory limit.
-- expect: exceeded the memory limit
local t = {}
local i = 0
while true do
  i = i + 1
  t[i] = {i, i, i}
end
