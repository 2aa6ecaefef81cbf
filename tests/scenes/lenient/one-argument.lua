-- One-argument forms of calls that take more: node:rotate(degrees) without its axis, gr.light
-- with a position alone, and gr.option with a name and no value. The rotation is ignored, the
-- light is the dark stand-in and the option is not set; the scene renders with its real light.
-- expect-error: one-argument.lua:10: node:rotate expects 2 arguments (axis, degrees), got 1
-- expect-lenient: node:rotate (arguments raybook cannot read: expects 2 arguments (axis, degrees), got 1; the call was ignored), first at one-argument.lua:10
-- expect-lenient: gr.light (arguments raybook cannot read: expects 3 arguments (position, colour, {c0,c1,c2}) or 6 (..., {length, width}, normal, left), got 1; a stand-in took its place), first at one-argument.lua:12
-- expect-lenient: gr.option (arguments raybook cannot read: expects 2 arguments (name, value), got 1; a stand-in took its place), first at one-argument.lua:13
-- expect-lit: 0.4 0.4 0.6 0.6
ball = gr.sphere('ball')
ball:rotate(30)
ball:scale(2, 2, 2)
local spot = gr.light({0, 5, 5})
gr.option('max_depth')
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0.2, 0.2, 0.2}, 10))
root = gr.node('root')
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0}), spot})
