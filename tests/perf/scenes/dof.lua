-- Benchmark scene "dof": raybook's version of POV-Ray's dof.pov and dof64.pov benchmark scenes
-- (../shared/peers/povray/: the mirror_glass scene, with its checker plane, seen through a focal
-- blur camera: aperture 0.4, focal point on the glass sphere). The body is
-- tests/perf/scenes/mirror_glass.lua (z mirrored, fovy 50 degrees; see its notes), except:
--   * the plane is POV-Ray's checker of unit squares (0.9 and 0.1 grey), built from 0.1-thick
--     tiles out to 60 units (procedural textures come in chapter 10); beyond them, black;
--   * the background is black: dof_vs_povray.sh gives POV-Ray's scene a black background too,
--     so both renderers blur the same silhouettes against the same colour;
--   * the lens: POV-Ray's `aperture 0.4` deflects the eye by at most aperture/2 times its sample
--     grid's radius 0.5 (tracepixel.cpp, JitterCameraRay), a disk 0.2 wide: raybook's aperture
--     0.2. The focus is |focal_point - location| = |(1.3, -1.5, -7.5)| = 7.7585 (z mirrored).
-- dof_vs_povray.sh sets the lens samples (--dof-samples N, with --aa=jittered --spp N: one
-- jittered pixel position and one lens stratum per ray).
gr.option('max_depth', 10)
gr.lens{aperture = 0.2, focus = 7.7585, samples = 16}
local light = gr.material({0.7 * 0.9, 0.7 * 0.9, 0.7 * 0.9}, {0, 0, 0}, 1)
local dark = gr.material({0.7 * 0.1, 0.7 * 0.1, 0.7 * 0.1}, {0, 0, 0}, 1)
local mirror = gr.material{kd = {0, 0, 0}, ks = {0.8, 0.8, 0.8}, shininess = 80, reflect = 0.9}
local glass = gr.material{kd = {0, 0, 0}, ks = {0.8, 0.8, 0.8}, shininess = 80,
                          transparency = 1, ior = 1.5}
local orange = gr.material({0.7 * 1.0, 0.7 * 0.6, 0.7 * 0.1}, {0.5, 0.5, 0.5}, 40)

local scene = gr.node('root')

-- The checker: unit tiles, top face at y = 0, from 10 units behind the eye to 60 in front.
for i = -40, 39 do
  for k = -60, 9 do
    local tile = gr.cube('tile')
    tile:scale(1, 0.1, 1)
    tile:translate(i, -0.1, k)
    tile:set_material((i + k) % 2 == 0 and light or dark)
    scene:add_child(tile)
  end
end

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
gr.render(scene, 'dof.png', 512, 512,
          {0, 2.5, 8}, {0, -1.5, -8}, {0, 1, 0}, 50,
          {ambient, ambient, ambient}, {l1, l2})
