-- A material call with a table where raybook expects a number (another course's shininess
-- {exponent}): the sphere wears the magenta stand-in.
-- expect-error: material-table.lua:8: gr.material: argument 3 (shininess) must be a number, got table
-- expect-lenient: gr.material (arguments raybook cannot read: argument 3 (shininess) must be a number, got table; a stand-in took its place), first at material-table.lua:8
-- expect-magenta: 0.4 0.4 0.6 0.6
root = gr.node('root')
ball = gr.sphere('ball')
ball:set_material(gr.material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, {25}))
ball:scale(2, 2, 2)
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})})
