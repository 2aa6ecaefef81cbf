-- A render call from another course, with trailing arguments of its own (a quality name and a
-- table of settings where raybook reads seed 001's aa and ss numbers). Under --lenient the
-- render reads its first ten arguments and leaves out the rest.
-- expect-error: render-extra-arguments.lua:12: gr.render: argument 11 (aa) must be a number, got string
-- expect-lenient: gr.render (arguments raybook cannot read: argument 11 (aa) must be a number, got string; read with its first 10 arguments), first at render-extra-arguments.lua:12
-- expect-lit: 0.4 0.4 0.6 0.6
root = gr.node('root')
ball = gr.sphere('ball')
ball:scale(2, 2, 2)
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0.2, 0.2, 0.2}, 10))
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})}, 'high', {samples = 4})
