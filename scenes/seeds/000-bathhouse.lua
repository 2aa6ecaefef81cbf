-- Seed 000, "Kabutack and Bathhouse", in seed 000's own dialect: materials are
-- gr.material(kd, ks, shininess, "reflect", r | "refract", ior | "glossy", fuzz, ...).
-- A small beetle robot rests beside a sunken bath in a Japanese bathhouse. Daylight falls
-- through a window in the roof; the water refracts the tiled basin and mirrors the room.
--
-- Chapters used: 1-3 (A4 scene), 4 ("reflect"), 5 ("refract"), 6 (the roof window is an
-- area light), 7 ("glossy"), 8 (10x supersampling). Parts of the seed's scene that wait for later chapters:
--   * gr.texture(material, "JapanWood.jpg") on the wood         chapter 10 (texture)
--   * steam above the water (volume scattering)                  chapter 17 (media)
--   * light bouncing off the water onto the walls (photon map)   chapter 16 (photon_map)
--   * depth of field                                             chapter 13
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
local shell     = gr.material({0.65, 0.05, 0.05}, {0.6, 0.6, 0.6}, 60, "reflect", 0.3)
local chrome    = gr.material({0.05, 0.05, 0.05}, {0.8, 0.8, 0.8}, 100, "reflect", 0.75)
-- A brushed-metal basin: a blurred mirror.
local brushed   = gr.material({0.1, 0.1, 0.1},    {0.7, 0.7, 0.7}, 50, "glossy", 0.2, "reflect", 0.6, "refract", 0)
-- Frosted glass, written as seed 000 writes it: every keyword, 0 where an effect is absent.
local frosted   = gr.material({0.0, 0.0, 0.0},    {0.5, 0.5, 0.5}, 35, "glossy", 0.1, "reflect", 0, "refract", 1.5)
-- Seen through the roof window: bright enough that ambient light alone saturates it.
local sky       = gr.material({3.0, 3.1, 3.3},    {0, 0, 0}, 1)

local scene = gr.node('bathhouse')

--- A box from corner lo to corner hi.
local function box(name, lo, hi, material)
  local b = gr.cube(name)
  b:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  b:translate(lo[1], lo[2], lo[3])
  b:set_material(material)
  scene:add_child(b)
  return b
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

-- The roof, with a window above the basin, and the daylight sky seen through it.
box('roof front', {-5, 3.3, -5.4}, {5, 3.5, 1}, darkWood)
box('roof back',  {-5, 3.3, -10.2}, {5, 3.5, -7.6}, darkWood)
box('roof left',  {-5, 3.3, -7.6}, {-2.2, 3.5, -5.4}, darkWood)
box('roof right', {0.4, 3.3, -7.6}, {5, 3.5, -5.4}, darkWood)
box('sky', {-2.4, 3.7, -7.8}, {0.6, 3.8, -5.2}, sky)
for _, x in ipairs({-1.55, -0.65}) do
  box('window bar', {x - 0.04, 3.3, -7.6}, {x + 0.04, 3.45, -5.4}, darkWood)
end

-- ---- Things on the deck -------------------------------------------------------------------------
-- Kabutack, a beetle robot: a lacquered shell, a chrome head with a long horn, glass eyes.
local robot = gr.node('kabutack')
robot:add_child(ellipsoid('shell', {0, 0.42, 0}, {0.55, 0.36, 0.75}, shell))
robot:add_child(ellipsoid('head', {0, 0.45, -0.75}, {0.3, 0.26, 0.26}, chrome))
local horn = ellipsoid('horn', {0, 0, 0}, {0.09, 0.38, 0.09}, shell)
horn:rotate('x', -40)
horn:translate(0, 0.78, -1.0)
robot:add_child(horn)
local fork = ellipsoid('horn tip', {0, 0, 0}, {0.16, 0.06, 0.06}, shell)
fork:translate(0, 1.06, -1.24)
robot:add_child(fork)
robot:add_child(ellipsoid('left eye', {-0.16, 0.52, -0.98}, {0.07, 0.07, 0.07}, glass))
robot:add_child(ellipsoid('right eye', {0.16, 0.52, -0.98}, {0.07, 0.07, 0.07}, glass))
for _, side in ipairs({-1, 1}) do
  for _, z in ipairs({-0.4, 0.0, 0.4}) do
    local leg = gr.cube('leg')
    leg:translate(-0.5, 0, -0.5)
    leg:scale(0.5, 0.08, 0.08)
    leg:rotate('z', side * -25)
    leg:translate(side * 0.6, 0.15, z)
    leg:set_material(darkWood)
    robot:add_child(leg)
  end
end
robot:rotate('y', 55)
robot:translate(2.3, 0, -5.6)
scene:add_child(robot)

-- A wooden bucket with a metal basin on it, and a glass bottle.
box('bucket', {-3.7, 0, -8.3}, {-2.9, 0.6, -7.5}, wood)
scene:add_child(ellipsoid('metal basin', {-3.3, 0.68, -7.9}, {0.45, 0.12, 0.45}, brushed))
scene:add_child(ellipsoid('bottle', {-2.3, 0.3, -7.5}, {0.22, 0.3, 0.22}, glass))
-- A frosted-glass lantern on a wooden post by the bath.
box('post', {3.4, 0, -8.1}, {3.6, 0.9, -7.9}, darkWood)
scene:add_child(ellipsoid('lantern shade', {3.5, 1.15, -8}, {0.3, 0.3, 0.3}, frosted))

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
gr.render(scene, '000-bathhouse.png', 320, 240,
          {0, 2, 0}, {0, -0.2, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {window, lantern})
