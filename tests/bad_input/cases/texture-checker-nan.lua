-- needs-feature: texture
-- A NaN in a checker colour.
-- expect: gr.texture: field 'checker', colour 2
local t = gr.texture{checker = {{1, 1, 1}, {0, 0/0, 0}}} --!
