-- Benchmark scene "mirror_glass": raybook's version of POV-Ray's mirror_glass.pov benchmark scene
-- (a mirror sphere, a glass sphere of ior 1.5 with Fresnel reflection, a small diffuse sphere
-- behind them, a plane, two point lights, max_trace_level 10, 512x512, no anti-aliasing).
-- Camera, lights, finishes and the plane translate as in spheres.lua (z mirrored, fovy 50°).
-- What differs, besides spheres.lua's list:
--   * the plane is plain grey 0.5 (POV's is a checker; procedural textures come in chapter 10);
--   * shadows of the glass sphere are opaque (raybook is Whitted-style, chapter 5); POV-Ray
--     traces filtered shadow rays through glass, so it does more work there.
gr.option('max_depth', 10)
local planeMat = gr.material({0.7 * 0.5, 0.7 * 0.5, 0.7 * 0.5}, {0, 0, 0}, 1)
local mirror = gr.material{kd = {0, 0, 0}, ks = {0.8, 0.8, 0.8}, shininess = 80, reflect = 0.9}
local glass = gr.material{kd = {0, 0, 0}, ks = {0.8, 0.8, 0.8}, shininess = 80,
                          transparency = 1, ior = 1.5}
local orange = gr.material({0.7 * 1.0, 0.7 * 0.6, 0.7 * 0.1}, {0.5, 0.5, 0.5}, 40)

local scene = gr.node('root')

local plane = gr.cube('plane')
plane:scale(2e5, 1, 2e5)
plane:translate(-1e5, -1, -1e5)
plane:set_material(planeMat)
scene:add_child(plane)

local spheres = {
  {'mirror', {-1.3, 1, -0.5}, 1, mirror},
  {'glass',  { 1.3, 1,  0.5}, 1, glass},
  {'orange', { 0.0, 0.6, -3}, 0.6, orange},
}
for _, s in ipairs(spheres) do
  local node = gr.nh_sphere(s[1], s[2], s[3])
  node:set_material(s[4])
  scene:add_child(node)
end

local l1 = gr.light({-5, 8, 6}, {0.8, 0.8, 0.8}, {1, 0, 0})
local l2 = gr.light({ 6, 6, 3}, {0.5, 0.5, 0.5}, {1, 0, 0})

local ambient = 0.1 / 0.7
gr.render(scene, 'mirror_glass.png', 512, 512,
          {0, 2.5, 8}, {0, -1.5, -8}, {0, 1, 0}, 50,
          {ambient, ambient, ambient}, {l1, l2})
