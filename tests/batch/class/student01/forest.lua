-- batch-expect: ok
-- A4, current framework: a row of trees made by a helper module in this folder.
require('trees')

local root = gr.node('root')
local grass = gr.cube('grass')
grass:scale(30, 1, 30)
grass:translate(-15, -1, -25)
grass:set_material(gr.material({0.3, 0.6, 0.25}, {0, 0, 0}, 1))
root:add_child(grass)

for i = 1, 5 do
  local t = make_tree('tree' .. i, 1 + (i % 3) * 0.5)
  t:translate((i - 3) * 2.2, 0, -i)
  root:add_child(t)
end

gr.render(root, 'forest.png', 160, 90,
          {0, 3, 9}, {0, -0.2, -1}, {0, 1, 0}, 50,
          {0.35, 0.35, 0.4}, {gr.light({5, 10, 8}, {0.9, 0.9, 0.8}, {1, 0, 0})})
