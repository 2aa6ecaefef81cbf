-- needs-feature: csg
-- Seed 001's node:csg takes 'u', 'n' or 'd'.
-- expect: node:csg: argument 2 (operation) must be 'u' (union), 'n' (intersection) or 'd' (difference), got 'x'
local a = gr.sphere('a')
a:csg(gr.sphere('b'), 'x') --!
