-- needs-feature: csg
-- A CSG operand must be a scene node.
-- expect: gr.difference: argument 2 (b) must be a scene node, got number
local a = gr.sphere('a')
local d = gr.difference(a, 3) --!
