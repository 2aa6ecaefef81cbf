-- batch-expect: ok
-- The TA's own check scene at the top of the class folder: three coloured balls on a slab.
local root = gr.node('root')
local colours = {{0.85, 0.2, 0.2}, {0.2, 0.75, 0.3}, {0.2, 0.35, 0.9}}
for i, kd in ipairs(colours) do
  local ball = gr.nh_sphere('ball' .. i, {(i - 2) * 2.2, 1, 0}, 1)
  ball:set_material(gr.material(kd, {0.5, 0.5, 0.5}, 30))
  root:add_child(ball)
end
local slab = gr.nh_box('slab', {-6, -1, -4}, 8)
slab:translate(0, -7, 0)
slab:set_material(gr.material({0.6, 0.6, 0.55}, {0, 0, 0}, 1))
root:add_child(slab)
gr.render(root, 'welcome.png', 160, 120,
          {0, 3, 9}, {0, -0.3, -1}, {0, 1, 0}, 45,
          {0.25, 0.25, 0.25}, {gr.light({-5, 8, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})})
