-- A current-era scene whose gr.render carries six values of its own after the ten (samples,
-- depth, aperture, ...). Under --lenient they are left out with a warning, never an error; and
-- the long call is no sign of the pre-2015 era: the wall, scaled then moved (the current way),
-- stays where its author put it, filling the image's lower half.
-- expect-error: render-long.lua:16: gr.render: argument 14 ({aperture, focalLength, dof}) must be a table of 3 numbers, got number
-- expect-stderr: rt:   gr.render (arguments raybook cannot read: argument 14 ({aperture, focalLength, dof}) must be a table of 3 numbers, got number; read with its first 10 arguments), first at render-long.lua:16
-- expect-no-stderr: pre-2015
-- expect-green: 0.3 0.7 0.7 0.9
-- expect-black: 0 0 1 0.4
root = gr.node('root')
wall = gr.cube('wall')
wall:scale(20, 4, 1)
wall:translate(-10, -4, 0)
wall:set_material(gr.material({0.1, 0.8, 0.1}, {0, 0, 0}, 1))
root:add_child(wall)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})}, 16, 5, 0.1, 2.8, 1, 64)
