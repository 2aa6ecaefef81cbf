-- io is not loaded in the sandbox.
-- expect: attempt to index a nil value (global 'io')
local f = io.open('/etc/passwd') --!
