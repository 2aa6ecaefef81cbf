-- needs-feature: csg
-- A CSG node needs two operands.
-- expect: gr.union expects 2 to 3 arguments (a, b [, name]), got 1
local a = gr.sphere('a')
local u = gr.union(a) --!
