-- dofile reads files, so the sandbox removes it.
-- expect: attempt to call a nil value (global 'dofile')
dofile('/etc/passwd') --!
