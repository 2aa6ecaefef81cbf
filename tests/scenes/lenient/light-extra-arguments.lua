-- A light whose extra arguments mean something else: another course's spot light, gr.light(
-- position, colour, falloff, 'spot', direction, angle). raybook reads six arguments as seed
-- 001's rectangular light; under --lenient it reads the first three, a point light.
-- expect-error: light-extra-arguments.lua:11: gr.light: argument 4 ({length, width}) must be a table of 2 numbers, got string
-- expect-lenient: gr.light (arguments raybook cannot read: argument 4 ({length, width}) must be a table of 2 numbers, got string; read with its first 3 arguments), first at light-extra-arguments.lua:11
-- expect-lit: 0.4 0.4 0.6 0.6
root = gr.node('root')
ball = gr.sphere('ball')
ball:scale(2, 2, 2)
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0.2, 0.2, 0.2}, 10))
local spot = gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0}, 'spot', {0, 0, -1}, 30)
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3}, {spot})
