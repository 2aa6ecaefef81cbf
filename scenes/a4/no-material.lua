-- rt-not-black: 0.05 0.1 0.45 0.9
-- no-material.lua: what a course user gets who forgets set_material. The course framework
-- would crash on these nodes; raybook draws a geometry node without a material of its own in
-- its nearest ancestor's material, and with none at all in a default grey (kd 0.5, no
-- specular). Left: a sphere and a box with no material anywhere (default grey). Right: the
-- same under a group node whose material is blue (inherited). Neither may come out black.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/no-material.lua   (writes no-material.png)

root = gr.node('root')

plain_ball = gr.sphere('plain_ball')
plain_ball:translate(-1.6, 0.4, 0)
root:add_child(plain_ball)
plain_box = gr.nh_box('plain_box', {-2.2, -1.6, -0.6}, 1.2)
root:add_child(plain_box)

painted = gr.node('painted')
painted:set_material(gr.material({0.2, 0.4, 0.9}, {0.5, 0.5, 0.5}, 30))
root:add_child(painted)
blue_ball = gr.sphere('blue_ball')
blue_ball:translate(1.6, 0.4, 0)
painted:add_child(blue_ball)
blue_box = gr.nh_box('blue_box', {1.0, -1.6, -0.6}, 1.2)
painted:add_child(blue_box)

gr.render(root, 'no-material.png', 240, 160,
          {0, 0.5, 7}, {0, -0.1, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {gr.light({-3, 6, 8}, {0.9, 0.9, 0.9}, {1, 0, 0})})
