-- needs-feature: photon_map
-- rt-args: --max-memory 64M
-- A hundred billion photons a pass cannot fit in 64 MiB: refused before any is traced,
-- naming the gr.render call whose photon pass it is.
-- expect: photon pass 1 (100000000000 photons)
gr.photons{count = 1e11}
local s = gr.sphere('s')
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1))
local glass = gr.sphere('g')
glass:set_material(gr.material{kd = {0, 0, 0}, ks = {0, 0, 0}, shininess = 1, ior = 1.5, transparency = 1})
glass:translate(0, 0, 2)
local root = gr.node('root')
root:add_child(s)
root:add_child(glass)
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, --!
          {0.1, 0.1, 0.1}, {gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})})
