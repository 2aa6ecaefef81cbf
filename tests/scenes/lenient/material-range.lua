-- A material call with a number outside raybook's range (a reflectivity of 1.5, which another
-- course's renderer clamps): the material is read without it, a plain green Phong material.
-- expect-error: material-range.lua:8: gr.material: argument 4 (reflectivity) must be from 0 to 1
-- expect-lenient: gr.material (arguments raybook cannot read: argument 4 (reflectivity) must be from 0 to 1; read with its first 3 arguments), first at material-range.lua:8
-- expect-green: 0.4 0.4 0.6 0.6
root = gr.node('root')
ball = gr.sphere('ball')
ball:set_material(gr.material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, 25, 1.5))
ball:scale(2, 2, 2)
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})})
