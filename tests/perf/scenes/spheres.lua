-- Benchmark scene "spheres": raybook's version of POV-Ray's spheres.pov benchmark scene (three Phong
-- spheres on a plane, two point lights, hard shadows, 512x512, no anti-aliasing).
--
-- Translation from POV-Ray (left-handed, z into the screen) to raybook (right-handed, -z into
-- the screen): every z coordinate changes sign, which gives the same picture.
--   camera   POV location <0,2.5,-8> look_at <0,1,0> angle 50 (HORIZONTAL fov, right = x*W/H).
--            A4's fovy is vertical: fovy = 2*atan(tan(50°/2) * H/W) = 50° at 512x512.
--   finish   POV: colour = ambient*pigment + diffuse*pigment*(N·L)*light
--                          + phong*(R·V)^phong_size*light (white highlight).
--            A4:  colour = kd*ambient + kd*(N·L)*I + ks*(R·V)^shininess*I, so
--            kd = diffuse*pigment = 0.7*pigment, ks = phong (grey), shininess = phong_size, and
--            the global ambient 0.1/0.7 turns kd*ambient into 0.1*pigment for every material
--            (all POV finishes here share ambient 0.1, diffuse 0.7).
--   lights   POV point lights without fade: falloff {1, 0, 0}.
-- What differs:
--   * the background is black (A4 has no background colour; POV's is rgb <0.2,0.3,0.5>);
--   * the infinite plane y = 0 is a box 2e5 wide whose top face is y = 0 (identical on screen
--     except within a fraction of a pixel of the horizon);
--   * A4 computes no highlight when N·L <= 0 (POV's phong does not test N·L);
--   * raybook writes linear values truncated to 8 bits; POV gamma-encodes its PNG.
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

local l1 = gr.light({-5, 8, 6}, {0.8, 0.8, 0.8}, {1, 0, 0})
local l2 = gr.light({ 6, 6, 3}, {0.5, 0.5, 0.5}, {1, 0, 0})

local ambient = 0.1 / 0.7
gr.render(scene, 'spheres.png', 512, 512,
          {0, 2.5, 8}, {0, -1.5, -8}, {0, 1, 0}, 50,
          {ambient, ambient, ambient}, {l1, l2})
