-- The figure of chapter 9's terminator section (docs/figures/ch09-terminator.png): the
-- 80-triangle icosphere with interpolated normals, lit from above, shadow rays from the flat
-- facets (left) and from the curved surface (right). Render from the repository root:
--   ./rt --features=all --output docs/figures/ch09-terminator.png docs/figures/ch09-terminator.lua
local clay = gr.material({0.8, 0.45, 0.3}, {0.4, 0.4, 0.4}, 40)
local root = gr.node('root')
local without = gr.smooth_mesh('without', '../../scenes/assets/icosphere80.obj', {terminator = false})
without:translate(-1.15, 0, 0)
without:set_material(clay)
root:add_child(without)
local with = gr.smooth_mesh('with', '../../scenes/assets/icosphere80.obj')
with:translate(1.15, 0, 0)
with:set_material(clay)
root:add_child(with)
gr.render(root, 'ch09-terminator.png', 320, 160, {0, 0, 7}, {0, 0, -1}, {0, 1, 0}, 25,
          {0.12, 0.12, 0.12}, {gr.light({-10, 40, -3}, {0.9, 0.9, 0.9}, {1, 0, 0})})
