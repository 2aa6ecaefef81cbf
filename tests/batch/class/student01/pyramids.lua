-- batch-expect: ok
-- A4, current framework: one OBJ mesh (pyramid.obj, beside this file) instanced three times.
local sand = gr.material({0.85, 0.7, 0.4}, {0.1, 0.1, 0.1}, 5)
local stone = gr.material({0.8, 0.75, 0.6}, {0.2, 0.2, 0.2}, 15)

local root = gr.node('root')
local desert = gr.cube('desert')
desert:scale(40, 1, 40)
desert:translate(-20, -1, -30)
desert:set_material(sand)
root:add_child(desert)

local sizes = {{-3, 1.0}, {0, 1.6}, {3.2, 1.2}}
for i, s in ipairs(sizes) do
  local p = gr.mesh('pyramid' .. i, 'pyramid.obj')
  p:scale(s[2], s[2], s[2])
  p:rotate('y', 20 * i)
  p:translate(s[1], 0, -2 * i)
  p:set_material(stone)
  root:add_child(p)
end

gr.render(root, 'pyramids.png', 160, 100,
          {0, 3, 10}, {0, -0.25, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {gr.light({-10, 12, 10}, {1, 0.95, 0.85}, {1, 0, 0})})
