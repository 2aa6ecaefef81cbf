-- open must be true or false, not a number.
-- expect: gr.cylinder: field 'open' must be true or false
local c = gr.cylinder{open = 1} --!
