-- Benchmark scene "mesh_L0": raybook's version of POV-Ray's mesh_L0.pov benchmark scene: the Stanford bunny,
-- bunny_L0 (the original npm 'bunny'), 3,674 flat triangles, on a plane, one point light, hard shadows, 512x512, no AA.
--
-- The OBJ path below is the benchmark's own copy of the bunny, which make bench expects beside
-- the repository (tests/perf/bench.sh says where); run from the repository root. POV-Ray's bunny_L0.inc holds the same vertices as the OBJ, but in
-- POV-Ray's left-handed space; raybook is right-handed, so every z changes sign: the camera and
-- the light are mirrored by hand and the bunny by scale(1, 1, -1).
--   camera   POV location <0,6,-16> look_at <0,4.5,0> angle 45 (HORIZONTAL fov); A4's fovy is
--            vertical: fovy = 2*atan(tan(45°/2) * H/W) = 45° at 512x512.
--   finish   kd = diffuse*pigment, ks = phong, shininess = phong_size; the global ambient
--            0.1/0.7 gives ambient*pigment = 0.1*pigment (both finishes: ambient 0.1, diffuse 0.7).
-- What differs: black background (POV: rgb <0.2,0.3,0.5>); the infinite plane is a box 2e5 wide
-- with its top at y = 0; no highlight where N·L <= 0; raybook's PNG is linear, POV's gamma-encoded.
local bunnyMat = gr.material({0.7 * 0.9, 0.7 * 0.85, 0.7 * 0.75}, {0.3, 0.3, 0.3}, 30)
local planeMat = gr.material({0.7 * 0.8, 0.7 * 0.8, 0.7 * 0.8}, {0, 0, 0}, 1)

local scene = gr.node('root')

local plane = gr.cube('plane')
plane:scale(2e5, 1, 2e5)
plane:translate(-1e5, -1, -1e5)
plane:set_material(planeMat)
scene:add_child(plane)

local bunny = gr.mesh('bunny', '../shared/assets/bunny_L0.obj')
bunny:scale(1, 1, -1)  -- POV-Ray's left-handed z
bunny:set_material(bunnyMat)
scene:add_child(bunny)

local light = gr.light({-8, 15, 10}, {1, 1, 1}, {1, 0, 0})

local ambient = 0.1 / 0.7
gr.render(scene, 'mesh_L0.png', 512, 512,
          {0, 6, 16}, {0, -1.5, -16}, {0, 1, 0}, 45,
          {ambient, ambient, ambient}, {light})
