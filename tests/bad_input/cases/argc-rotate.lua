-- node:rotate with an axis vector instead of an axis name: the extra argument is tolerated (the
-- course framework ignores it), but the axis the call reads has the wrong type.
-- expect: node:rotate: argument 2 (axis) must be a string, got number
local n = gr.node('n')
n:rotate(0, 1, 0, 45) --!
