-- Reading a file after closing it is an error at the line of the read.
-- expect: attempt to use a closed file
local f = io.open('objs/no-faces.obj')
f:close()
local line = f:read('l') --!
