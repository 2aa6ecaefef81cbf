-- Two 1 GiB strings: the second must be refused by the memory limit (2 GiB by default).
-- expect: exceeded the memory limit of 2.0 GiB for scripts
local a = string.rep('a', 1 << 30)
local b = string.rep('b', 1 << 30)
