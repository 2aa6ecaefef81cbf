-- io.popen is left out of the sandbox's read-only io, and the message says why.
-- expect: io.popen is not available in raybook's sandbox
-- expect: read-only
-- expect: --unsafe-lua
local p = io.popen('touch pwned.txt') --!
