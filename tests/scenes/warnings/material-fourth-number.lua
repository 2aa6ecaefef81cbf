-- A student's extended gr.material(kd, ks, shininess, reflectivity, ...): the numeric fourth
-- argument is read as the reflectivity and the rest are ignored, with one warning.
-- expect-warning: gr.material: read numeric argument 4 as the reflectivity
-- expect-warning: ignored arguments 5-6
root = gr.node('root')
s = gr.sphere('s')
s:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 25, 0.3, 1.5, 0)) --!
root:add_child(s)
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})})
