-- The sandbox opens files for reading only: a write mode is refused and no file is made.
-- expect: io.open('out.txt', 'w')
-- expect: reading only (mode 'r' or 'rb')
-- expect: --unsafe-lua
local f = io.open('out.txt', 'w') --!
f:write('pwned')
