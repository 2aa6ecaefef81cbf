-- set_material given a table instead of a material.
-- expect: node:set_material: argument 2 (material) must be a material, got table
local n = gr.sphere('n')
n:set_material({0.5, 0.5, 0.5}) --!
