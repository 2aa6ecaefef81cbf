-- needs-feature: media
-- node:set_medium takes a medium; its arguments are numbered as node:set_material's are
-- (the node itself is argument 1).
-- expect: node:set_medium: argument 2 (medium) must be a medium (from gr.medium), got number
local ball = gr.sphere('ball')
ball:set_medium(42) --!
