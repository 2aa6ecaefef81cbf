-- The camera looks away from the only sphere (view +z, sphere at -z).
-- expect-warning: no shape is in front of the camera
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, 1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
