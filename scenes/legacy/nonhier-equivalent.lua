-- rt-era: modern
-- nonhier-equivalent.lua: the modern (Lua 5.4) form of nonhier-2013.lua: the same
-- non-hierarchical primitives with the same node transforms, listed in the order they apply.
-- nonhier-2013.lua rendered with --legacy must give exactly this picture.

gold  = gr.material({0.9, 0.8, 0.4}, {0.8, 0.8, 0.4}, 25)
blue  = gr.material({0.3, 0.4, 0.9}, {0.5, 0.5, 0.5}, 40)
red   = gr.material({0.9, 0.2, 0.15}, {0.6, 0.6, 0.6}, 60)
stone = gr.material({0.65, 0.6, 0.55}, {0.1, 0.1, 0.1}, 5)

root = gr.node('root')

ground = gr.nh_box('ground', {-10, -20, -10}, 20)
ground:set_material(stone)
root:add_child(ground)

s1 = gr.nh_sphere('s1', {-3, 1, 0}, 1)
s1:set_material(gold)
root:add_child(s1)

s2 = gr.nh_sphere('s2', {0, 0.5, 0}, 0.5)
s2:scale(2, 2, 2)
s2:set_material(blue)
root:add_child(s2)

s3 = gr.nh_sphere('s3', {3, 0, 0}, 0.5)
s3:scale(1, 0.5, 1)
s3:translate(0, 1, 0)
s3:set_material(red)
root:add_child(s3)

b1 = gr.nh_box('b1', {1, 0, 2}, 1)
b1:rotate('y', 30)
b1:translate(0, 0, -1)
b1:set_material(gold)
root:add_child(b1)

gr.render(root, 'nonhier-2013.png', 320, 200,
          {0, 4, 10}, {0, -0.35, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {gr.light({-6, 10, 8}, {0.9, 0.9, 0.9}, {1, 0, 0})})
