-- Benchmark scene "soft": raybook's version of POV-Ray's soft.pov benchmark scene: spheres.lua with
-- the first point light replaced by a 2x2 rectangular area light sampled 8x8 with jitter
-- (all 64 shadow rays, no adaptive sampling), 512x512, no anti-aliasing.
-- What differs, besides spheres.lua's list: raybook's panel is a one-sided Lambertian emitter
-- facing down (chapter 6), so each sample is weighted by its cosine towards the shading point;
-- POV-Ray's area light is an array of point lights. The shadow-ray count is the same.
local Fin = function(r, g, b)
  return gr.material({0.7 * r, 0.7 * g, 0.7 * b}, {0.6, 0.6, 0.6}, 40)
end
local planeMat = gr.material({0.7 * 0.8, 0.7 * 0.8, 0.7 * 0.8}, {0, 0, 0}, 1)

local scene = gr.node('root')

local plane = gr.cube('plane')
plane:scale(2e5, 1, 2e5)
plane:translate(-1e5, -1, -1e5)
plane:set_material(planeMat)
scene:add_child(plane)

local spheres = {
  {'red',   {-2.2, 1,  0.0}, Fin(1.0, 0.2, 0.2)},
  {'green', { 0.0, 1, -1.5}, Fin(0.2, 1.0, 0.2)},
  {'blue',  { 2.2, 1,  0.0}, Fin(0.2, 0.3, 1.0)},
}
for _, s in ipairs(spheres) do
  local node = gr.nh_sphere(s[1], s[2], 1)
  node:set_material(s[3])
  scene:add_child(node)
end

local l1 = gr.area_light{position = {-5, 8, 6}, colour = {0.8, 0.8, 0.8}, falloff = {1, 0, 0},
                         size = {2, 2}, normal = {0, -1, 0}, left = {1, 0, 0}, samples = 8}
local l2 = gr.light({ 6, 6, 3}, {0.5, 0.5, 0.5}, {1, 0, 0})

local ambient = 0.1 / 0.7
gr.render(scene, 'soft.png', 512, 512,
          {0, 2.5, 8}, {0, -1.5, -8}, {0, 1, 0}, 50,
          {ambient, ambient, ambient}, {l1, l2})
