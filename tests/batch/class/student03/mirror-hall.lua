-- batch-expect: ok
-- Seed 001's dialect: a gr.phongMat mirror behind a ball, a gr.transMat glass cube in front,
-- and a rectangular ceiling light (the six-argument gr.light).
local floor  = gr.phongMat({0.6, 0.6, 0.6}, {0.2, 0.2, 0.2}, 20, 0.1, 0)
local mirror = gr.phongMat({0.05, 0.05, 0.05}, {0.8, 0.8, 0.8}, 200, 0.9, 0)
local red    = gr.phongMat({0.8, 0.15, 0.1}, {0.5, 0.5, 0.5}, 50, 0, 0)
local glass  = gr.transMat({0.9, 0.95, 1.0}, 1.5, 0.8, 0)

root = gr.node('root')
ground = gr.cube('ground')
ground:translate(-5, -1, -6)
ground:scale(10, 1, 10)
ground:set_material(floor)
root:add_child(ground)

pane = gr.cube('pane')
pane:translate(-3, 0, -4)
pane:scale(6, 3, 0.1)
pane:set_material(mirror)
root:add_child(pane)

ball = gr.sphere('ball')
ball:translate(-0.8, 0.8, -1.5)
ball:scale(0.8, 0.8, 0.8)
ball:set_material(red)
root:add_child(ball)

block = gr.cube('block')
block:translate(0.6, 0, 0)
block:scale(0.8, 0.8, 0.8)
block:set_material(glass)
root:add_child(block)

panel = gr.light({0, 4, -1}, {0.9, 0.9, 0.9}, {1, 0, 0}, {2, 2}, {0, -1, 0}, {1, 0, 0})
gr.render(root, 'mirror-hall.png', 160, 120,
          {0, 2, 5}, {0, -0.3, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {panel}, 0, 2, 0, {0, 0, 0})
