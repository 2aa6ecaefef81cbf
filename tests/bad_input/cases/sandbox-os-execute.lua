-- os is not loaded in the sandbox.
-- expect: attempt to index a nil value (global 'os')
os.execute('touch pwned.txt') --!
