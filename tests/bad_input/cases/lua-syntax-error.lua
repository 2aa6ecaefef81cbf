-- A Lua syntax error: the message names the file and line and what the parser saw.
-- expect: unexpected symbol near '='
local root = gr.node('root')
local x = = 1 --!
