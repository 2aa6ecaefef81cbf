-- A method called with a dot instead of a colon: the message says how to call it.
-- expect: call methods with a colon
local n = gr.node('n')
n.translate(1, 2, 3) --!
