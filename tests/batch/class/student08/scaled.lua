-- batch-expect: error
-- Broken at run time: node:scale with one number too few.
local root = gr.node('root')
local box = gr.cube('box')
box:scale(2, 2)
box:set_material(gr.material({0.3, 0.6, 0.9}, {0.3, 0.3, 0.3}, 20))
root:add_child(box)
gr.render(root, 'scaled.png', 64, 48, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})
