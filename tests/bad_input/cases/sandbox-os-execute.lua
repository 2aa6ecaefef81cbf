-- os is not loaded in the sandbox, and the message says why and how to allow it.
-- expect: 'os' is not available
-- expect: sandbox
-- expect: --unsafe-lua
os.execute('touch pwned.txt') --!
