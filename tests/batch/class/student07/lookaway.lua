-- batch-expect: ok
-- Renders, with a warning: the camera looks away from the only ball, so the picture can only
-- be background. (The student flipped the sign of the view direction.)
local root = gr.node('root')
local ball = gr.sphere('ball')
ball:translate(0, 0, -5)
ball:set_material(gr.material({0.8, 0.6, 0.2}, {0.3, 0.3, 0.3}, 20))
root:add_child(ball)
gr.render(root, 'lookaway.png', 80, 60, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})
