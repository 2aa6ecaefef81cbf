-- gr.sphere with no name.
-- expect: gr.sphere expects 1 argument (name), got 0
local s = gr.sphere() --!
