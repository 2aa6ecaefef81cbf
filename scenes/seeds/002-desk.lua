-- Seed 002, "YacRay": a paper coffee cup beside a pair of glasses on a desk, lit by a
-- desk lamp. Written in seed 002's own dialect:
--   gr.fancy_material(kd, ks, shininess, reflectivity, ior, transparency, glossiness)
--   gr.ball_light(position, colour, falloff, radius)
--   gr.obj_mesh(name, file)
-- The cup and the glasses' rims are surfaces of revolution, built here in Lua as smooth
-- triangle meshes with gr.smooth_mesh's table form (vertices and 0-based faces).
--
-- Chapters used: 1-3 (A4 scene, meshes), 4 (reflectivity), 5 (ior, transparency: the lenses),
-- 6 (gr.ball_light), 7 (glossiness: the desk), 8 (adaptive supersampling), 9 (smooth shading of
-- the cup, the rims and seed 002's obj_mesh rabbit), 10 (set_texture_map: the desk's wood;
-- gr.texture: the sleeve's print), 11 (the cup's pressed ridges, a bump image), 12 (Reinhard's
-- global tone map) and 15 (the sleeve is an open cone frustum).
-- Chapters 13 and 14 are not used: seed 002 asked for neither depth of field nor CSG.
-- Parts of the seed's scene that wait for later chapters: none (photon mapping and media were
-- not among seed 002's objectives).

-- ---- Materials (seed 002's gr.fancy_material) ----------------------------------------------
--                            kd                   ks                 shin  refl  ior  transp gloss
local desk     = gr.fancy_material({0.42, 0.25, 0.13}, {0.3, 0.3, 0.3},    40, 0.25, 1.0, 0,    0.12)
local wall     = gr.fancy_material({0.72, 0.74, 0.7},  {0, 0, 0},           1, 0,    1.0, 0,    0)
local paper    = gr.fancy_material({0.86, 0.83, 0.76}, {0.15, 0.15, 0.15}, 10, 0,    1.0, 0,    0)
local band     = gr.fancy_material({0.6, 0.08, 0.06},  {0.15, 0.15, 0.15}, 10, 0,    1.0, 0,    0)
-- Coffee: dark, and as smooth as a mirror.
local coffee   = gr.fancy_material({0.12, 0.06, 0.03}, {0.6, 0.6, 0.6},   150, 0.3,  1.0, 0,    0)
-- Spectacle lenses: clear glass. Frames: dark tortoiseshell with a soft sheen.
local lens     = gr.fancy_material({0.0, 0.0, 0.0},    {0.8, 0.8, 0.8},   200, 0,    1.5, 0.95, 0)
local frame    = gr.fancy_material({0.12, 0.07, 0.04}, {0.5, 0.5, 0.5},    60, 0.1,  1.0, 0,    0)
-- A glazed ceramic rabbit.
local glaze    = gr.fancy_material({0.2, 0.35, 0.55},  {0.7, 0.7, 0.7},    90, 0.2,  1.0, 0,    0)

-- The desk's wood (seed 002's set_texture_map, chapter 10); the sleeve's print (raybook's
-- gr.texture, which can wrap an image round a cylinder); the cup's pressed ridges (chapter 11:
-- seed 002's ridges.png, through raybook's set_bump so that it too wraps round, 16 x 3 times).
desk:set_texture_map('../assets/textures/wood.jpg')
band:set_texture(gr.texture{image = '../assets/textures/cup.png', mapping = 'cylindrical',
                            scale = {-1, -0.5}, offset = {1, 0.5}, wrap = 'clamp'})
paper:set_bump{pattern = 'image', file = '../assets/textures/ridges.png', strength = 0.004,
               mapping = 'cylindrical', scale = {3, 1}}

local root = gr.node('root')

--- A surface of revolution about the y axis: `profile` is a list of {radius, height} points,
--- turned through `segments` steps. Returns a smooth mesh node (chapter 9): its normals are
--- averaged across the faces within 60 degrees, so the wall is round and the rim's edges stay.
local function lathe(name, profile, segments)
  local vertices, faces = {}, {}
  local n = #profile
  for i = 0, segments - 1 do
    local a = 2 * math.pi * i / segments
    for _, p in ipairs(profile) do
      vertices[#vertices + 1] = {p[1] * math.cos(a), p[2], p[1] * math.sin(a)}
    end
  end
  for i = 0, segments - 1 do
    local j = (i + 1) % segments
    for k = 0, n - 2 do
      faces[#faces + 1] = {i * n + k, i * n + k + 1, j * n + k + 1, j * n + k}
    end
  end
  return gr.smooth_mesh(name, vertices, faces)
end

--- The profile of a ring (torus) of tube radius rho at distance R from the axis.
local function ringProfile(R, rho, steps)
  local p = {}
  for s = 0, steps do
    local t = 2 * math.pi * s / steps
    p[#p + 1] = {R + rho * math.cos(t), rho * math.sin(t)}
  end
  return p
end

-- ---- The room ---------------------------------------------------------------------------------
local top = gr.cube('desk top')
top:scale(8, 0.3, 5.5)
top:translate(-4, -0.3, -3)
top:set_material(desk)
root:add_child(top)
local back = gr.cube('wall')
back:scale(12, 8, 0.2)
back:translate(-6, -3, -3.2)
back:set_material(wall)
root:add_child(back)

-- ---- The paper cup: a tapered wall with a rolled rim, filled with coffee -----------------------
local cupProfile = {
  {0.0, 0.0}, {0.27, 0.0},      -- the base
  {0.37, 1.0},                   -- the outer wall
  {0.385, 1.01}, {0.39, 1.03}, {0.38, 1.05}, {0.365, 1.04},   -- the rolled rim
  {0.36, 1.0}, {0.355, 0.94},    -- the inner wall down to the coffee
  {0.0, 0.94},                   -- the coffee's level: the cup is closed here
}
local cup = lathe('cup', cupProfile, 48)
cup:set_material(paper)
local cupNode = gr.node('cup node')
cupNode:add_child(cup)
-- The coffee sits just above the cup's closing disk, so the two never meet.
local surface = gr.sphere('coffee')
surface:scale(0.355, 0.004, 0.355)
surface:translate(0, 0.943, 0)
surface:set_material(coffee)
cupNode:add_child(surface)
-- A printed sleeve around the cup: an open cone frustum (chapter 15), the narrow end down,
-- just outside the wall from height 0.25 to 0.6. The frustum's own y runs from 1 (bottom, after
-- the half turn) to -1 (top), and the turn mirrors its angle: the texture's scale and offset turn
-- both back, so the band reads left to right and upright.
local sleeve = gr.cone{name = 'sleeve', top_radius = 0.302 / 0.337, open = true}
sleeve:rotate('x', 180)
sleeve:scale(0.337, 0.175, 0.337)
sleeve:translate(0, 0.425, 0)
sleeve:set_material(band)
cupNode:add_child(sleeve)
cupNode:translate(-0.7, 0, -0.6)
root:add_child(cupNode)

-- ---- The glasses, folded, lying on the desk -----------------------------------------------------
local glasses = gr.node('glasses')
for _, x in ipairs({-0.36, 0.36}) do
  local l = gr.sphere('lens')
  l:scale(0.3, 0.22, 0.035)
  l:translate(x, 0, 0)
  l:set_material(lens)
  glasses:add_child(l)
  local rim = lathe('rim', ringProfile(1, 0.1, 8), 32)
  rim:rotate('x', 90)
  rim:scale(0.31, 0.23, 0.31)
  rim:translate(x, 0, 0)
  rim:set_material(frame)
  glasses:add_child(rim)
  -- A folded temple (arm), running behind the lenses.
  local arm = gr.cube('temple')
  arm:scale(0.62, 0.03, 0.03)
  -- From the hinge at the rim's outer edge inwards; the two arms lie at different depths.
  arm:translate(x > 0 and 0.02 or -0.64, 0.06, x > 0 and -0.2 or -0.12)
  arm:set_material(frame)
  glasses:add_child(arm)
end
local bridge = gr.cube('bridge')
bridge:scale(0.14, 0.03, 0.03)
bridge:translate(-0.07, 0.1, -0.015)
bridge:set_material(frame)
glasses:add_child(bridge)
-- Lean the glasses back a little and turn them towards the camera.
glasses:rotate('x', -20)
glasses:rotate('y', -15)
glasses:translate(0.75, 0.24, -0.1)
root:add_child(glasses)

-- ---- A ceramic rabbit (seed 002's gr.obj_mesh; the path is relative to this file) ---------------
local bunny = gr.obj_mesh('rabbit', '../assets/bunny.obj')
bunny:scale(0.05, 0.05, 0.05)
bunny:rotate('y', 30)
bunny:translate(1.55, 0, -1.9)
bunny:set_material(glaze)
root:add_child(bunny)

-- ---- Lights: the desk lamp's bulb (seed 002's ball light) and a dim point light as fill ---------
local bulb = gr.ball_light({-2.2, 2.6, 1.0}, {0.95, 0.88, 0.75}, {1, 0, 0.02}, 0.25)
local fill = gr.light({3, 3, 4}, {0.25, 0.27, 0.32}, {1, 0, 0})

-- Keep it quick: few glossy directions and light samples.
gr.option('glossy_samples', 9)
gr.option('light_samples', 3)
-- Seed 002's objective 5, adaptive supersampling (chapter 8; the seed names no call for it).
gr.antialias{sampler = 'adaptive'}
-- Seed 002's objective 9, Reinhard's global tone map (chapter 12; the seed names no call). The
-- colours were chosen for linear output, so the sRGB curve stays off (it washes them out); 0.7
-- stops of exposure bring the desk and the cup to mid-grey and white.
gr.tone_map{operator = 'global', srgb = false, exposure = 0.7}
gr.render(root, '002-desk.png', 320, 240,
          {0.2, 2.2, 3.2}, {-0.2, -1.7, -3.6}, {0, 1, 0}, 38,
          {0.25, 0.25, 0.25}, {bulb, fill})
