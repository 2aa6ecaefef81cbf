-- An A4 scene without a light (and without gr.integrator('path')) can only be black.
-- expect: a scene needs at least one light
local root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'x.png', 8, 8, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 40, {0, 0, 0}, {}) --!
