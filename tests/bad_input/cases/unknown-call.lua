-- A call that no chapter provides.
-- expect: gr.teapot is not a raybook call
local t = gr.teapot('t') --!
