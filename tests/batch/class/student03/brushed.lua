-- batch-expect: ok
-- Seed 001's dialect: a blurry (glossy) gr.phongMat floor under two plain balls.
local brushed = gr.phongMat({0.3, 0.3, 0.35}, {0.6, 0.6, 0.6}, 80, 0.6, 0.2)
local green   = gr.phongMat({0.2, 0.7, 0.3}, {0.4, 0.4, 0.4}, 40, 0, 0)
local blue    = gr.phongMat({0.2, 0.3, 0.8}, {0.4, 0.4, 0.4}, 40, 0, 0)

root = gr.node('root')
plate = gr.cube('plate')
plate:translate(-4, -1, -6)
plate:scale(8, 1, 8)
plate:set_material(brushed)
root:add_child(plate)

b1 = gr.sphere('b1')
b1:translate(-1, 0.7, -2)
b1:scale(0.7, 0.7, 0.7)
b1:set_material(green)
root:add_child(b1)

b2 = gr.sphere('b2')
b2:translate(1, 0.7, -2.5)
b2:scale(0.7, 0.7, 0.7)
b2:set_material(blue)
root:add_child(b2)

gr.render(root, 'brushed.png', 128, 96,
          {0, 2, 4}, {0, -0.4, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({2, 5, 3}, {0.9, 0.9, 0.9}, {1, 0, 0})}, 0, 0, 2, {0, 0, 0})
