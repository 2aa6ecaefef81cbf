-- batch-expect: skipped helper
-- trees.lua: a helper module for forest.lua (require('trees')). It only defines a function.
function make_tree(name, height)
  local leaf = gr.material({0.15, 0.55, 0.2}, {0.1, 0.1, 0.1}, 10)
  local bark = gr.material({0.4, 0.25, 0.12}, {0, 0, 0}, 1)
  local tree = gr.node(name)
  local trunk = gr.cube(name .. '-trunk')
  trunk:scale(0.3, height, 0.3)
  trunk:translate(-0.15, 0, -0.15)
  trunk:set_material(bark)
  tree:add_child(trunk)
  local crown = gr.sphere(name .. '-crown')
  crown:scale(0.9, 1.2, 0.9)
  crown:translate(0, height + 0.6, 0)
  crown:set_material(leaf)
  tree:add_child(crown)
  return tree
end
