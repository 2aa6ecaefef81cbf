-- rt-args: --legacy
-- rt-era: legacy
-- rt-same-as: nonhier-equivalent.lua
-- nonhier-2013.lua: a pre-2015 (Lua 5.1) course scene whose non-hierarchical primitives also
-- carry node transforms. In the old framework an nh_sphere's centre and radius (an nh_box's
-- corner and size) describe the shape in the node's own frame; the node's transforms, listed
-- in reverse (post-multiplied), then place that shape. So 'translate(0, 2, 0)' on a sphere of
-- radius 0.5 centred at (3, 0, 0) moves it to (3, 2, 0), and 'scale(2, 2, 2)' on it gives a
-- sphere of radius 1 centred at (6, 0, 0).
-- Render it with --legacy: it must give exactly the picture of nonhier-equivalent.lua.
-- The flag cannot be dropped: the scene uses only calls both frameworks share (gr.material,
-- gr.node, gr.nh_sphere, gr.nh_box, scale/translate/rotate, gr.light, gr.render) and no table
-- mesh, unpack or string.gfind, so nothing in it tells its era, and without the flag rt takes
-- it for a current scene (its line says the order matters and no sign decides it).

gold  = gr.material({0.9, 0.8, 0.4}, {0.8, 0.8, 0.4}, 25)
blue  = gr.material({0.3, 0.4, 0.9}, {0.5, 0.5, 0.5}, 40)
red   = gr.material({0.9, 0.2, 0.15}, {0.6, 0.6, 0.6}, 60)
stone = gr.material({0.65, 0.6, 0.55}, {0.1, 0.1, 0.1}, 5)

root = gr.node('root')

ground = gr.nh_box('ground', {-10, -20, -10}, 20)
ground:set_material(stone)
root:add_child(ground)

-- An untransformed sphere for reference: centre (-3, 1, 0), radius 1.
s1 = gr.nh_sphere('s1', {-3, 1, 0}, 1)
s1:set_material(gold)
root:add_child(s1)

-- Radius 0.5 at (0, 0.5, 0), scaled by 2 about the origin: radius 1 at (0, 1, 0).
s2 = gr.nh_sphere('s2', {0, 0.5, 0}, 0.5)
s2:scale(2, 2, 2)
s2:set_material(blue)
root:add_child(s2)

-- Radius 0.5 at (3, 0, 0), then moved up by 1 and squashed in y, listed in reverse:
-- scale(1, 0.5, 1) happens first, so it is an ellipsoid at (3, 1, 0), 0.25 tall.
s3 = gr.nh_sphere('s3', {3, 0, 0}, 0.5)
s3:translate(0, 1, 0)
s3:scale(1, 0.5, 1)
s3:set_material(red)
root:add_child(s3)

-- A unit box with its minimum corner at (1, 0, 2), turned 30 degrees about y (about the
-- origin, not about the box), then moved back by 1.
b1 = gr.nh_box('b1', {1, 0, 2}, 1)
b1:translate(0, 0, -1)
b1:rotate('y', 30)
b1:set_material(gold)
root:add_child(b1)

gr.render(root, 'nonhier-2013.png', 320, 200,
          {0, 4, 10}, {0, -0.35, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {gr.light({-6, 10, 8}, {0.9, 0.9, 0.9}, {1, 0, 0})})
