-- An unknown statement.
-- expect: malformed-statement.obj:5: unknown statement 'vx'
local m = gr.mesh('m', 'objs/malformed-statement.obj') --!
