-- The same material under Whitted's integrator (the A4 default) is A4's own business: no warning.
-- expect-no-warning
root = gr.node('root')
local ball = gr.sphere('ball')
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0.6, 0.6, 0.6}, 20))
root:add_child(ball)
gr.render(root, 'out.png', 16, 16, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
