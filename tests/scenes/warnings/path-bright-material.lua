-- A path-traced scene with a material that would reflect more light than it receives (A4's
-- usual kd 0.8 and ks 0.6): the path tracer scales it down and says so, naming the node.
-- expect-warning: the material of 'ball' reflects more light than it receives
-- expect-warning: 1.4
gr.integrator('path')
root = gr.node('root')
local ball = gr.sphere('ball')
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0.6, 0.6, 0.6}, 20))
root:add_child(ball)
gr.render(root, 'out.png', 16, 16, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
