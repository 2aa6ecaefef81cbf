-- The CSG benchmark scene: tests/perf/povray/csg_spheres_boxes.pov for raybook (the peers'
-- csg.pov without its cylinders and cones, which are chapter 15's). POV-Ray's left-handed
-- coordinates become raybook's by z -> -z; its plane y = 0 is a thin box 100 units wide; its
-- finish (ambient 0.1, diffuse 0.7, phong 0.6, phong_size 40) becomes kd = 0.7 x colour,
-- ks = 0.6, shininess 40 and an ambient light of 0.1.
local function fin(r, g, b) return gr.material({0.7 * r, 0.7 * g, 0.7 * b}, {0.6, 0.6, 0.6}, 40) end
local root = gr.node('root')

local plane = gr.cube('plane')
plane:scale(100, 1, 100)
plane:translate(-50, -1, -50)
plane:set_material(gr.material({0.56, 0.56, 0.56}, {0, 0, 0}, 1))
root:add_child(plane)

-- box minus sphere
local box = gr.nh_box('box', {-1, 0, -1}, 2)
local ball = gr.nh_sphere('ball', {0, 1, 0}, 1.3)
local cut = gr.difference(box, ball)
cut:set_material(fin(1.0, 0.2, 0.2))
cut:translate(-2.6, 0, 0)
root:add_child(cut)

-- lens: intersection of two spheres
local lens = gr.intersection(gr.nh_sphere('l1', {-0.6, 1, 0}, 1.2), gr.nh_sphere('l2', {0.6, 1, 0}, 1.2))
lens:set_material(fin(0.2, 1.0, 0.2))
lens:translate(0, 0, -1)
root:add_child(lens)

gr.render(root, 'csg.png', 512, 512, {0, 3.5, 9}, {0, -2.5, -9}, {0, 1, 0}, 50, {0.1, 0.1, 0.1},
          {gr.light({-5, 8, 6}, {0.8, 0.8, 0.8}, {1, 0, 0}), gr.light({6, 6, 3}, {0.5, 0.5, 0.5}, {1, 0, 0})})
