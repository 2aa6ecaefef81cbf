-- Seed 000, "Kabutack and Bathhouse", in seed 000's own dialect: materials are
-- gr.material(kd, ks, shininess, "reflect", r | "refract", ior | "glossy", fuzz, ...).
-- A small beetle robot rests beside a sunken bath in a Japanese bathhouse. Daylight falls
-- through a window in the roof; the water refracts the tiled basin and mirrors the room.
--
-- Chapters used: 1-3 (A4 scene), 4 ("reflect"), 5 ("refract"), 6 (the roof window is an
-- area light), 7 ("glossy": the polished deck and the brushed basin), 8 (10x supersampling),
-- 10 (gr.texture: the wood), 11 (ripples on the water), 13 (depth of field, focused on the
-- robot), 14 (the roof's window opening, the robot's shell and the hollow bucket are CSG),
-- 15 (cylinders: the robot's legs and horn fork, the bucket, the post; a cone: the horn) and
-- 16 (a caustic map: the window's light refracted by the rippled water draws bright ripples on
-- the basin's floor, and the light the water reflects plays on the walls, seed 000's
-- objective 8, which it gave up on) and 17 (media: steam over the hot water, seed 000's
-- "volume scattering ... smoke effects", the objective it called the hardest).
-- Chapters 9 and 12 are not used: the scene has no meshes, and seed 000 asked for no tone map.
-- Seed 000 documented no call for CSG, quadrics, bump, the lens or media, so those use
-- raybook's own calls (gr.difference, gr.cylinder, gr.cone, set_bump, gr.lens, gr.medium);
-- the focus distance is seed 000's rule, |target - eye|.
-- Seed 000 has no light call of its own (its roof window was to be "a planar light
-- source"), so the window uses raybook's gr.area_light from chapter 6.

-- ---- Materials (seed 000's gr.material) ------------------------------------------------------
local wood      = gr.material({0.55, 0.36, 0.2},  {0.15, 0.12, 0.1}, 12)
local darkWood  = gr.material({0.34, 0.2, 0.11},  {0.1, 0.08, 0.06}, 12)
-- The polished deck reflects a little, blurred: seed 000's glossy reflection.
local deck      = gr.material({0.5, 0.34, 0.2},   {0.2, 0.18, 0.15}, 30, "glossy", 0.12, "reflect", 0.18)
local plaster   = gr.material({0.85, 0.82, 0.74}, {0.05, 0.05, 0.05}, 5)
local tile      = gr.material({0.3, 0.55, 0.6},   {0.3, 0.3, 0.3}, 40)
local stone     = gr.material({0.42, 0.42, 0.4},  {0.1, 0.1, 0.1}, 10)
local mountain  = gr.material({0.22, 0.38, 0.62}, {0, 0, 0}, 1)
local snow      = gr.material({0.95, 0.95, 0.97}, {0, 0, 0}, 1)
-- Clear water: seed 000's "refract" makes a material fully transparent with that index.
local water     = gr.material({0.0, 0.0, 0.0},    {0.5, 0.5, 0.5}, 80, "refract", 1.33)
local glass     = gr.material({0.0, 0.0, 0.0},    {0.8, 0.8, 0.8}, 150, "refract", 1.5)
-- The robot's shell is lacquered: a mirror reflection on top of its red Phong colour.
local shell     = gr.material({0.65, 0.05, 0.05}, {0.6, 0.6, 0.6}, 60, "reflect", 0.2)
local chrome    = gr.material({0.05, 0.05, 0.05}, {0.8, 0.8, 0.8}, 100, "reflect", 0.75)
-- A brushed-metal basin: a blurred mirror.
local brushed   = gr.material({0.1, 0.1, 0.1},    {0.7, 0.7, 0.7}, 50, "glossy", 0.2, "reflect", 0.6, "refract", 0)
-- Frosted glass, written as seed 000 writes it: every keyword, 0 where an effect is absent.
local frosted   = gr.material({0.0, 0.0, 0.0},    {0.5, 0.5, 0.5}, 35, "glossy", 0.1, "reflect", 0, "refract", 1.5)
-- Seen through the roof window: bright enough that ambient light alone saturates it.
local sky       = gr.material({3.0, 3.1, 3.3},    {0, 0, 0}, 1)

-- Seed 000's gr.texture puts the wood image on the wood materials (chapter 10).
gr.texture(wood, '../assets/textures/wood.jpg')
gr.texture(darkWood, '../assets/textures/wood.jpg')
gr.texture(deck, '../assets/textures/wood.jpg')
-- Ripples on the water (chapter 11, raybook's set_bump; seed 000 names no bump call), spreading
-- from two drops; in the water box's object space, a unit cube.
water:set_bump{pattern = 'ripples', strength = 0.003, wavelength = 0.06,
               centres = {{0.35, 1, 0.45}, {0.7, 1, 0.7}}}

-- Chapter 16 (raybook's gr.photons; seed 000 named no call): one pass of a million caustic
-- photons. The water reflects a few percent of what reaches it, so the walls' share of the
-- photons is sparse: a gather of the usual radius finds a handful there and draws the glow as
-- speckle. at_least = 32 grows such a gather until it holds 32 photons (up to 3 radii), so the
-- glow comes out smooth; the basin's dense caustics keep their sharp radius.
gr.photons{count = 1000000, passes = 1, at_least = 32}

local scene = gr.node('bathhouse')

--- A box from corner lo to corner hi, not yet in the scene (a CSG operand).
local function solid(name, lo, hi, material)
  local b = gr.cube(name)
  b:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  b:translate(lo[1], lo[2], lo[3])
  b:set_material(material)
  return b
end

--- A box from corner lo to corner hi, added to the scene.
local function box(name, lo, hi, material)
  local b = solid(name, lo, hi, material)
  scene:add_child(b)
  return b
end

--- A capped cylinder (chapter 15) of radius r from height y0 to y1, on the vertical axis at (x, z).
local function post(name, x, z, r, y0, y1, material)
  local c = gr.cylinder(name)
  c:scale(r, (y1 - y0) / 2, r)
  c:translate(x, (y0 + y1) / 2, z)
  c:set_material(material)
  return c
end

--- An ellipsoid with centre c and radii r.
local function ellipsoid(name, c, r, material)
  local s = gr.sphere(name)
  s:scale(r[1], r[2], r[3])
  s:translate(c[1], c[2], c[3])
  s:set_material(material)
  return s
end

-- ---- The room ----------------------------------------------------------------------------------
-- The deck around a sunken basin at x in [-3, 1.2], z in [-7, -3.6].
box('deck front', {-5, -1, -3.6}, {5, 0, 1}, deck)
box('deck back',  {-5, -1, -10},  {5, 0, -7}, deck)
box('deck left',  {-5, -1, -7},   {-3, 0, -3.6}, deck)
box('deck right', {1.2, -1, -7},  {5, 0, -3.6}, deck)
-- The basin: tiled floor, and its walls are the deck's inner faces.
box('basin', {-3, -1.1, -7}, {1.2, -0.9, -3.6}, tile)
-- The water fills the basin up to 0.15 below the deck; it overlaps the basin's floor and walls
-- slightly, so that every surface under water lies inside the water.
box('water', {-3.02, -0.98, -7.02}, {1.22, -0.15, -3.58}, water)
-- Stepping stones.
scene:add_child(ellipsoid('stone 1', {-2.2, -0.2, -4.6}, {0.35, 0.14, 0.3}, stone))
scene:add_child(ellipsoid('stone 2', {-1.2, -0.22, -5.5}, {0.3, 0.12, 0.28}, stone))

-- Walls: plaster above a wooden wainscot, with a painted mountain (a tilted cube, so its top
-- corner is the peak) rising above the wainscot.
box('back wall', {-5, 0, -10.2}, {5, 3.3, -10}, plaster)
box('left wall', {-5.2, 0, -10}, {-5, 3.3, 1}, plaster)
box('right wall', {5, 0, -10}, {5.2, 3.3, 1}, plaster)
local fuji = gr.cube('mountain')
fuji:translate(-0.5, -0.5, 0)
fuji:rotate('z', 45)
fuji:scale(2.6, 1.5, 0.02)
fuji:translate(-0.8, 0.9, -9.99)
fuji:set_material(mountain)
scene:add_child(fuji)
local cap = gr.cube('snow cap')
cap:translate(-0.5, -0.5, 0)
cap:rotate('z', 45)
cap:scale(0.9, 0.52, 0.02)
cap:translate(-0.8, 1.66, -9.97)
cap:set_material(snow)
scene:add_child(cap)
box('wainscot', {-5, 0, -9.99}, {5, 1.2, -9.9}, darkWood)
for i = -4, 4 do
  box('plank', {i * 1.1 - 0.03, 0, -9.9}, {i * 1.1 + 0.03, 1.2, -9.88}, wood)
end

-- The roof: one slab with the window cut out of it (chapter 14's difference; seed 000 names no
-- CSG call, so this is raybook's gr.difference), and the daylight sky seen through it.
local roof = gr.difference(solid('roof slab', {-5, 3.3, -10.2}, {5, 3.5, 1}, darkWood),
                           solid('window hole', {-2.2, 3.2, -7.6}, {0.4, 3.6, -5.4}, darkWood),
                           'roof')
scene:add_child(roof)
box('sky', {-2.4, 3.7, -7.8}, {0.6, 3.8, -5.2}, sky)
for _, x in ipairs({-1.55, -0.65}) do
  box('window bar', {x - 0.04, 3.3, -7.6}, {x + 0.04, 3.45, -5.4}, darkWood)
end

-- ---- Things on the deck -------------------------------------------------------------------------
-- Kabutack, a beetle robot, of primitives and CSG (chapters 14 and 15, raybook's calls): a
-- lacquered shell split into two wing cases by a groove, a chrome head, a forked horn (a cone
-- with a crossbar), glass eyes, and six cylinder legs. It faces -z in its own frame.
local robot = gr.node('kabutack')
local dome = ellipsoid('shell', {0, 0.42, 0}, {0.55, 0.36, 0.75}, shell)
local groove = solid('wing groove', {-0.04, 0.62, -0.3}, {0.04, 0.9, 0.9}, darkWood)
local belly = solid('flat belly', {-1, -0.5, -1}, {1, 0.16, 1}, shell)
robot:add_child(gr.difference(gr.difference(dome, groove, 'wing cases'), belly, 'shell'))
robot:add_child(ellipsoid('head', {0, 0.45, -0.75}, {0.3, 0.26, 0.26}, chrome))
local horn = gr.cone{name = 'horn', top_radius = 0.35}
horn:scale(0.1, 0.28, 0.1)
horn:rotate('x', -40)
horn:translate(0, 0.78, -1.0)
horn:set_material(shell)
robot:add_child(horn)
local fork = gr.cylinder('horn fork')
fork:scale(0.045, 0.16, 0.045)
fork:rotate('z', 90)
fork:translate(0, 0.99, -1.18)
fork:set_material(shell)
robot:add_child(fork)
robot:add_child(ellipsoid('left eye', {-0.16, 0.52, -0.98}, {0.07, 0.07, 0.07}, glass))
robot:add_child(ellipsoid('right eye', {0.16, 0.52, -0.98}, {0.07, 0.07, 0.07}, glass))
for _, side in ipairs({-1, 1}) do
  for _, z in ipairs({-0.4, 0.0, 0.4}) do
    local leg = gr.cylinder('leg')
    leg:scale(0.04, 0.25, 0.04)
    leg:rotate('z', side * 65)
    leg:translate(side * 0.6, 0.15, z)
    leg:set_material(darkWood)
    robot:add_child(leg)
  end
end
robot:scale(1.25, 1.25, 1.25)
robot:rotate('y', 150)
robot:translate(2.3, 0, -5.3)
scene:add_child(robot)

-- A wooden bucket with a metal basin on it, and a glass bottle.
-- The bucket is a cylinder hollowed by a smaller one (chapters 14 and 15).
scene:add_child(gr.difference(post('bucket', -3.3, -7.9, 0.4, 0, 0.6, wood),
                              post('bucket inside', -3.3, -7.9, 0.34, 0.06, 0.7, wood), 'bucket'))
scene:add_child(ellipsoid('metal basin', {-3.3, 0.68, -7.9}, {0.45, 0.12, 0.45}, brushed))
scene:add_child(ellipsoid('bottle', {-2.3, 0.3, -7.5}, {0.22, 0.3, 0.22}, glass))
-- A frosted-glass lantern on a wooden post by the bath.
scene:add_child(post('post', 3.5, -8, 0.1, 0, 0.9, darkWood))
scene:add_child(ellipsoid('lantern shade', {3.5, 1.15, -8}, {0.3, 0.3, 0.3}, frosted))

-- ---- Steam (chapter 17) ----------------------------------------------------------------
-- Steam rises from the hot water: wisps of chapter 11's noise in a box over the bath (a cube
-- without a material of its own only bounds its medium).
local steam = gr.cube('steam')
steam:scale(4.2, 1.4, 3.4)
steam:translate(-3, -0.15, -7)
steam:set_medium(gr.medium{sigma_s = 3, sigma_a = 0.05, g = 0.3,
                           density = {noise = 2.2, octaves = 3, bias = 0.05, gain = 1.2, seed = 7}})
scene:add_child(steam)
-- Single scattering: light scattered once more would mostly come from the bright sky above the
-- window, a few very bright paths that ten rays per pixel cannot average into smooth steam.
gr.option('media_bounces', 0)

-- ---- Lights --------------------------------------------------------------------------------------
-- Daylight through the roof window (an area light, chapter 6), and a warm lantern.
local window  = gr.area_light{position = {-0.9, 3.25, -6.5}, colour = {0.95, 0.93, 0.88},
                              falloff = {1, 0, 0}, size = {2.6, 2.2},
                              normal = {0, -1, 0}, left = {1, 0, 0}}
local lantern = gr.light({3.5, 2.4, -1.5}, {0.45, 0.32, 0.18}, {1, 0, 0.04})

-- Keep it quick: few glossy directions and light samples, and a shallow recursion.
gr.option('max_depth', 4)
gr.option('glossy_samples', 4)
gr.option('light_samples', 3)
-- Seed 000's "10x super-sampling": ten random positions in each pixel (chapter 8).
gr.antialias{sampler = 'random', samples = 10}
-- Seed 000's depth of field (chapter 13): a small lens focused, by seed 000's rule, at the
-- length of the view vector, written as target - eye to reach the robot's depth (5.5 along the
-- view); its 10 lens samples pair with the 10 pixel samples.
gr.lens{aperture = 0.1, samples = 10}
gr.render(scene, '000-bathhouse.png', 320, 240,
          {0, 2, 0}, {0, -1.081, -5.404}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {window, lantern})
