-- A string that doubles without bound must stop at the memory limit.
-- It runs under --max-memory 512M, so that it stops within a second or two;
-- memory-string-rep checks the default limit of 2 GiB.
-- expect: exceeded the memory limit
-- rt-args: --max-memory 512M
local s = 'x'
while true do s = s .. s end
