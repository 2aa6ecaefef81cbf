-- io is not loaded in the sandbox, and the message says why and how to allow it.
-- expect: 'io' is not available
-- expect: sandbox
-- expect: --unsafe-lua
local f = io.open('/etc/passwd') --!
