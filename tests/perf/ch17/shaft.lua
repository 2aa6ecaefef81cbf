-- Chapter 17 against POV-Ray 3.7 (tests/perf/ch17/media_vs_povray.sh): a light shaft through a
-- window into a box of homogeneous fog. The same scene is tests/perf/povray/chapter17-media.pov;
-- keep the two in step. Run with --media-bounces=0 (single scattering, as POV-Ray's media).
--   floor: x in [-1, 2], z in [-2, 2], top at y = 0, grey (kd 0.5);
--   a wall at x in [-1.1, -1] from y 0 to 4, z in [-2, 2], with a window y in [1.0, 1.6],
--   z in [-0.4, 0.2];
--   fog: the box [-1, 1.5] x [-0.05, 2] x [-1.5, 1.5] (its bottom below the floor's top: no
--   coplanar faces), sigma_s 0.3, sigma_a 0.03, isotropic (g 0);
--   one point light without falloff at (-3, 3, -0.1), intensity 8; black background;
--   camera at (0.2, 1.1, 3.4) looking along (-0.1, -0.15, -1), 55 degrees.
gr.option('max_depth', 2)
local grey = gr.material{kd = {0.5, 0.5, 0.5}, ks = {0, 0, 0}, shininess = 1}
local root = gr.node('root')
local function box(name, x0, y0, z0, x1, y1, z1)
  local b = gr.cube(name)
  b:scale(x1 - x0, y1 - y0, z1 - z0)
  b:translate(x0, y0, z0)
  b:set_material(grey)
  root:add_child(b)
end
box('floor',        -1,   -0.1, -2,   2,  0,   2)
box('wall below',   -1.1,  0,   -2,  -1,  1.0, 2)
box('wall above',   -1.1,  1.6, -2,  -1,  4,   2)
box('wall behind',  -1.1,  1.0, -2,  -1,  1.6, -0.4)
box('wall front',   -1.1,  1.0,  0.2, -1, 1.6, 2)

local fog = gr.cube('fog')
fog:scale(2.5, 2.05, 3)
fog:translate(-1, -0.05, -1.5)
fog:set_medium(gr.medium{sigma_s = 0.3, sigma_a = 0.03, g = 0})
root:add_child(fog)

local light = gr.light({-3, 3, -0.1}, {8, 8, 8}, {1, 0, 0})
gr.render(root, 'ch17-shaft.png', 160, 120, {0.2, 1.1, 3.4}, {-0.1, -0.15, -1}, {0, 1, 0}, 55,
          {0, 0, 0}, {light})
