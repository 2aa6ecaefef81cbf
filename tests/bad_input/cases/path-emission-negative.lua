-- needs-feature: path_tracing
-- A surface cannot emit negative light: refused, naming the field.
-- expect: gr.material: field 'emission'
local lamp = gr.material{emission = {1, -2, 1}} --!
