-- io is read-only in the sandbox and reads only under the scene's folder and the --assets
-- folders: an absolute path outside them is refused, and the message says what is allowed.
-- expect: io.open: cannot read '/etc/passwd'
-- expect: raybook's sandbox reads only files under the scene's folder
-- expect: tests/bad_input/cases
-- expect: --unsafe-lua
local f = io.open('/etc/passwd') --!
