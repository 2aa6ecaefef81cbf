-- rt-stats: [^0-9]3696 triangles
-- showcase.lua: all seventeen chapters in one picture, a small sculpture gallery.
--   1 ray casting     spheres and boxes
--   2 Phong, shadows  Phong materials; instancing: 600 floor tiles made of two nodes, five
--                     columns of one, a ring of twelve pearls of one sphere; a warm point lamp
--                     on the right with hard shadows
--   3 meshes, BVH     the Stanford bunny (3,674 triangles) loaded once and shown on four
--                     plinths; an icosahedron; the painting's quad
--   4 mirrors         a framed standing mirror that shows the gold bunny's other side and the
--                     frosted ball, a chrome ball, a polished marble floor
--   5 refraction      a glass globe filled with water that holds an air bubble (nested media:
--                     the IOR stack), a glass icosahedron
--   6 soft shadows    a large softbox panel high on the left: every shadow it casts is soft
--   7 glossy          a steel ball, a frosted-glass ball, a satin-gold bunny
--   8 antialiasing    jittered 5 x 5 rays a pixel (gr.antialias): smooth edges, and 25 paths
--                     a pixel to average the soft shadows, glossy surfaces and lens
--   9 smooth meshes   the bunnies are smooth (gr.smooth_mesh: normals computed from the
--                     faces), not faceted
--  10 textures        a painting on the back wall (poster.png on seed 000's plane.obj, by its
--                     vt), wood grain on the mirror's frame and foot and the lens's post
--  11 bump mapping    a hammered steel ball and a rough-hewn jade block (noise bumps)
--  12 tone mapping    Reinhard's global operator (key 0.3, white at the brightest pixel)
--                     brings the chrome and glass highlights back from clipping; the output
--                     stays linear (srgb = false), as the colours were chosen for
--  13 depth of field  a thin lens (disk aperture 0.12) focused 11 units away, on the middle
--                     row: the gold bunny, the CSG pieces, the frosted ball; the balls in front
--                     and the columns and painting behind are softly out of focus
--  14 CSG             a jade block with a ball bitten out of its corner (a difference; the
--                     bite keeps the porcelain of the ball that cut it) and a glass lens, the
--                     intersection of two spheres, standing on edge on a post
--  15 cylinders/cones the column shafts are capped cylinders; the lens's post a small one; a
--                     glass paperweight is a cone frustum whose caps refract (seed 001's were
--                     black)
--  16 photon mapping  a caustic map (gr.photons): the glass paperweight, the icosahedron and
--                     the lens focus the softbox's light into their shadows, which chapter 5
--                     left dark; the chrome ball and the mirror throw reflected light on the
--                     floor. The marble floor's faint, broad reflection would send a dim glow
--                     onto the walls that needs many more photons to come out smooth, so its
--                     materials say caustics = false (POV-Ray asks each object the same).
--                     Two passes of 50,000 photons: the picture takes about 1.4 times as long
--                     as without them (the defaults, 16 passes of 20,000, about 3 times).
--  17 media           a wisp of grey smoke rises from a bronze censer left of the centre
--                     (the chapter's VDB plume, assets/plume.nvdb), lit by the softbox: light
--                     scattered once (media_bounces 0), delta tracking through the grid. The
--                     picture takes about 1.2 times the CPU time it takes without it.
--
-- Run:  make demo, which runs  ./rt --features=all scenes/showcase.lua  (writes showcase.png,
-- the README's docs/images/showcase.png). The scene sets its own sampler, lens and tone map;
-- --features=all,-dof (or -tone_map, -bump, ...) shows the picture without one chapter.
-- Meshes and images are named relative to this file's folder.
-- The rt-stats line above is checked by tests/scenes/run_all.sh: 3,696 unique triangles (the
-- bunny's 3,674 once, however often it is shown, the icosahedron's 20 and the painting's 2).
gr.option('max_depth', 6)
gr.option('light_samples', 2)   -- 2 x 2 points on each area light, per camera ray
gr.option('glossy_samples', 4)  -- per camera ray: 25 rays a pixel make 100 of each
gr.antialias{sampler = 'jittered', samples = 25}          -- chapter 8
gr.lens{aperture = 0.12, focus = 11.0, samples = 25}      -- chapter 13
gr.tone_map{operator = 'global', key = 0.3, srgb = false} -- chapter 12
gr.photons{count = 50000, passes = 2}                     -- chapter 16

local marbleA = gr.material{kd = {0.76, 0.72, 0.64}, ks = {0.3, 0.3, 0.3},
                            shininess = 80, reflect = 0.12, caustics = false}
local marbleB = gr.material{kd = {0.26, 0.27, 0.30}, ks = {0.3, 0.3, 0.3},
                            shininess = 80, reflect = 0.12, caustics = false}
local stone   = gr.material{kd = {0.62, 0.58, 0.52}, ks = {0.15, 0.15, 0.15}, shininess = 20}
local column  = gr.material{kd = {0.80, 0.76, 0.70}, ks = {0.15, 0.15, 0.15}, shininess = 15}
local wallM   = gr.material{kd = {0.50, 0.24, 0.19}, ks = {0, 0, 0}, shininess = 1}
local ceilM   = gr.material{kd = {0.30, 0.22, 0.16}, ks = {0, 0, 0}, shininess = 1}
local wood    = gr.material{kd = {0.40, 0.24, 0.12}, ks = {0.3, 0.3, 0.3}, shininess = 40}
local jade    = gr.material{kd = {0.20, 0.58, 0.40}, ks = {0.5, 0.6, 0.5}, shininess = 70}
local porcel  = gr.material{kd = {0.88, 0.86, 0.82}, ks = {0.6, 0.6, 0.6}, shininess = 120}
local ruby    = gr.material{kd = {0.70, 0.08, 0.12}, ks = {0.8, 0.7, 0.7}, shininess = 120}
-- Chapter 4: a mirror adds r times what it sees to its (here almost black) Phong colour.
local mirror  = gr.material{kd = {0.02, 0.02, 0.02}, ks = {0.2, 0.2, 0.2},
                            shininess = 200, reflect = 0.9}
local chrome  = gr.material{kd = {0.04, 0.04, 0.05}, ks = {0.8, 0.8, 0.8},
                            shininess = 150, reflect = 0.8}
-- Chapter 5: clear glass, water and air.
local glass   = gr.material{kd = {0.04, 0.04, 0.04}, ks = {0.6, 0.6, 0.6}, shininess = 250,
                            ior = 1.5, transparency = 0.95}
local water   = gr.material{kd = {0.02, 0.05, 0.08}, ks = {0, 0, 0}, shininess = 1,
                            ior = 1.33, transparency = 0.97}
local air     = gr.material{kd = {0, 0, 0}, ks = {0, 0, 0},
                            shininess = 1, ior = 1.0, transparency = 1.0}
-- Chapter 7: glossy metal and frosted glass.
local gold    = gr.material{kd = {0.60, 0.42, 0.10}, ks = {0.7, 0.6, 0.35}, shininess = 60,
                            reflect = 0.12, glossiness = 0.2}
local steel   = gr.material{kd = {0.08, 0.08, 0.10}, ks = {0.6, 0.6, 0.6}, shininess = 60,
                            reflect = 0.7, glossiness = 0.25}
local frosted = gr.material{kd = {0.10, 0.16, 0.24}, ks = {0.5, 0.5, 0.5}, shininess = 80,
                            ior = 1.5, transparency = 0.85, glossiness = 0.08}

-- Chapter 10: wood grain, and a painting on the wall.
wood:set_texture(gr.texture{image = 'assets/textures/wood.jpg'})
local canvas = gr.material{kd = {0.8, 0.8, 0.8}, ks = {0, 0, 0}, shininess = 1}
canvas:set_texture('kd', 'assets/textures/poster.png')
-- Chapter 11: a hammered steel ball and a rough-hewn jade block.
steel:set_bump{pattern = 'noise', strength = 0.01, scale = 0.3, octaves = 2, seed = 7}
local carved = gr.material{kd = {0.20, 0.58, 0.40}, ks = {0.5, 0.6, 0.5}, shininess = 70}
carved:set_bump{pattern = 'noise', strength = 0.04, scale = 0.15, octaves = 2, seed = 3}

local scene = gr.node('gallery')

-- The room. The floor: 30 x 20 tiles of two polished marbles (600 instances of two nodes).
local tiles = {}
for k, m in ipairs({marbleA, marbleB}) do
  local t = gr.cube('tile' .. k)
  t:scale(0.98, 0.2, 0.98)
  t:translate(0.01, -0.2, 0.01)
  t:set_material(m)
  tiles[k] = t
end
local floor = gr.node('floor')
for i = 0, 29 do
  for j = 0, 19 do
    local place = gr.node('tile_' .. i .. '_' .. j)
    place:translate(i - 15, 0, j - 9)
    place:add_child(tiles[(i + j) % 2 + 1])
    floor:add_child(place)
  end
end
scene:add_child(floor)
local grout = gr.nh_box('grout', {-40, -80.19, -60}, 80)
grout:set_material(gr.material{kd = {0.1, 0.1, 0.1}})
scene:add_child(grout)
-- Walls all round and a ceiling, so mirrors and glossy surfaces always have a room to show.
local function slab(name, x0, y0, z0, x1, y1, z1, m)
  local s = gr.cube(name)
  s:scale(x1 - x0, y1 - y0, z1 - z0)
  s:translate(x0, y0, z0)
  s:set_material(m)
  scene:add_child(s)
end
slab('back', -20, -0.2, -11, 20, 14, -10, wallM)
slab('front', -20, -0.2, 16, 20, 14, 17, wallM)
slab('left', -17, -0.2, -11, -16, 14, 17, wallM)
slab('right', 16, -0.2, -11, 17, 14, 17, wallM)
slab('ceiling', -20, 12, -11, 20, 13, 17, ceilM)

-- Chapter 10: a painting between the two right-hand columns: seed 000's 2 x 2 quad, whose vt
-- map the poster onto it, stood up against the back wall (2.7 x 1.8: the poster's 3 : 2).
local painting = gr.mesh('painting', 'assets/textures/plane.obj')
painting:rotate('x', 90)
painting:scale(1.35, 0.9, 1)
painting:translate(1.95, 3.6, -9.98)
painting:set_material(canvas)
scene:add_child(painting)

-- A colonnade along the back wall: one column (base, ellipsoid shaft, capital), five times.
local col = gr.node('column')
local cbase = gr.nh_box('cbase', {-0.45, 0, -0.45}, 0.9)
cbase:set_material(column)
col:add_child(cbase)
local shaft = gr.cylinder('shaft')   -- chapter 15: a real cylinder, base to capital
shaft:scale(0.32, 2.3, 0.32)
shaft:translate(0, 3.2, 0)
shaft:set_material(column)
col:add_child(shaft)
local capital = gr.cube('capital')
capital:scale(1.0, 0.35, 1.0)
capital:translate(-0.5, 5.5, -0.5)
capital:set_material(column)
col:add_child(capital)
for i = -2, 2 do
  local place = gr.node('column' .. i)
  place:translate(3.4 * i, 0, -7.5)
  place:add_child(col)
  scene:add_child(place)
end
slab('beam', -7.5, 5.85, -8.1, 7.5, 6.35, -6.9, column)

-- The bunny (about 9.7 tall, feet at y = 0), loaded once, shown on four plinths.
local bunny = gr.smooth_mesh('bunny', 'assets/bunny.obj')
local function exhibit(name, x, z, height, size, turn, material)
  local w = 8 * size
  slab(name .. '-plinth', x - w / 2, 0, z - w / 2, x + w / 2, height, z + w / 2, stone)
  local painted = gr.node(name .. '-bunny')
  painted:set_material(material)
  painted:add_child(bunny)
  painted:scale(size, size, size)
  painted:rotate('y', turn)
  painted:translate(x, height, z)
  scene:add_child(painted)
end
exhibit('centre', 0, -2.6, 0.9, 0.34, 20, gold)
exhibit('left', -2.4, -5.4, 0.6, 0.2, 45, jade)
exhibit('right', 5.0, -4.6, 0.6, 0.2, -15, ruby)
exhibit('far', 7.3, -3.6, 0.5, 0.18, -40, porcel)

-- A tall standing mirror on the left, turned towards the middle of the room.
local stand = gr.node('standing mirror')
local function part(name, x0, y0, z0, x1, y1, z1, m)
  local p = gr.cube(name)
  p:scale(x1 - x0, y1 - y0, z1 - z0)
  p:translate(x0, y0, z0)
  p:set_material(m)
  stand:add_child(p)
end
part('glass', -1.5, 0.35, -0.05, 1.5, 4.2, 0.05, mirror)
part('frame-left', -1.65, 0, -0.1, -1.5, 4.35, 0.1, wood)
part('frame-right', 1.5, 0, -0.1, 1.65, 4.35, 0.1, wood)
part('frame-top', -1.65, 4.2, -0.1, 1.65, 4.35, 0.1, wood)
part('frame-bottom', -1.65, 0.2, -0.1, 1.65, 0.35, 0.1, wood)
part('foot', -1.4, 0, -0.5, 1.4, 0.12, 0.5, wood)
stand:rotate('y', 55)
stand:translate(-4.9, 0, -1.2)
scene:add_child(stand)

-- The glass globe on a low plinth: glass, water inside it, an air bubble inside the water.
slab('globe-plinth', 3.3, 0, -1.6, 4.9, 0.5, 0.0, stone)
local globe = gr.nh_sphere('globe', {4.1, 1.55, -0.8}, 1.05)
globe:set_material(glass)
scene:add_child(globe)
local inner = gr.nh_sphere('water', {4.1, 1.55, -0.8}, 0.9)
inner:set_material(water)
scene:add_child(inner)
local bubble = gr.nh_sphere('bubble', {3.85, 1.85, -0.55}, 0.3)
bubble:set_material(air)
scene:add_child(bubble)

-- Chapter 14: a jade block with a ball bitten out of its top corner (the bite is porcelain),
-- and a glass lens, the intersection of two spheres, standing on edge on a small post.
local block = gr.cube('csg-block')
block:set_material(carved)
local bite = gr.nh_sphere('csg-bite', {1, 1, 1}, 0.75)
bite:set_material(porcel)
local bitten = gr.difference(block, bite, 'bitten block')
bitten:scale(0.7, 0.7, 0.7)
bitten:rotate('y', -50)
bitten:translate(2.6, 0, 1.2)
scene:add_child(bitten)
local lens = gr.intersection(gr.nh_sphere('lens-a', {0, 0, 0.8}, 1),
                             gr.nh_sphere('lens-b', {0, 0, -0.8}, 1), 'lens')
lens:set_material(glass)
lens:scale(0.9, 0.9, 0.9)
lens:rotate('y', -50)
lens:translate(-0.9, 0.74, 0.6)
scene:add_child(lens)
local post = gr.cylinder('lens post')
post:scale(0.06, 0.1, 0.06)
post:translate(-0.9, 0.1, 0.6)
post:set_material(wood)
scene:add_child(post)
-- Chapter 15: a glass paperweight, a cone frustum whose caps refract.
local weight = gr.cone{name = 'paperweight', top_radius = 0.6}
weight:scale(0.45, 0.3, 0.45)
weight:translate(-1.4, 0.3, 3.2)
weight:set_material(glass)
scene:add_child(weight)

-- In front: a chrome ball, a brushed-steel ball and a glass icosahedron; round the centre
-- plinth, a ring of small porcelain pearls (one sphere, twelve instances).
for _, s in ipairs({{-2.6, 0.5, 2.9, chrome}, {3.1, 0.45, 3.0, steel}}) do
  local ball = gr.nh_sphere('ball', {s[1], s[2], s[3]}, s[2])
  ball:set_material(s[4])
  scene:add_child(ball)
end
local icosa = gr.mesh('icosa', 'assets/icosa.obj')
icosa:set_material(glass)
icosa:scale(0.34, 0.34, 0.34)
icosa:rotate('z', 15)
icosa:translate(0.3, 0.53, 3.1)
scene:add_child(icosa)
local pearl = gr.sphere('pearl')
pearl:scale(0.2, 0.2, 0.2)
pearl:translate(0, 0.2, 0)
pearl:set_material(porcel)
for k = 0, 11 do
  local place = gr.node('pearl' .. k)
  place:translate(2.1, 0, 0)
  place:rotate('y', k * 360 / 12)
  place:translate(0, 0, -2.6)
  place:add_child(pearl)
  scene:add_child(place)
end

-- A frosted-glass ball on a pedestal, next to the clear globe: what lies behind it blurs.
slab('pedestal', 1.3, 0, 0.3, 2.1, 1.0, 1.1, stone)
local frostedBall = gr.nh_sphere('frosted', {1.7, 1.5, 0.7}, 0.5)
frostedBall:set_material(frosted)
scene:add_child(frostedBall)

-- Chapter 17: a wisp of smoke rises from a bronze censer by the mirror (the chapter's VDB
-- plume, assets/plume.nvdb, 1 x 2 x 1, here 1.3 wide and 2.6 tall). An empty node only bounds
-- its medium. The softbox lights it from above, and the light is scattered once: the smoke is
-- dense, so its inside is in its own shadow and it reads grey. Light scattered many times
-- would whiten it, but at 25 paths a pixel it draws bright speckles in the wisp.
local bronze = gr.material{kd = {0.42, 0.27, 0.12}, ks = {0.6, 0.45, 0.3}, shininess = 50}
local censer = gr.cylinder('censer')
censer:scale(0.32, 0.12, 0.32)
censer:translate(-2.3, 0.12, 0.5)
censer:set_material(bronze)
scene:add_child(censer)
local smoke = gr.node('smoke')
smoke:set_medium(gr.medium{sigma_s = 40, sigma_a = 0.5, g = 0.3,
                           density = {file = 'assets/plume.nvdb', grid = 'density'}})
smoke:scale(1.3, 1.3, 1.3)
smoke:translate(-2.3, 0.24, 0.5)
scene:add_child(smoke)
gr.option('media_bounces', 0)

-- Lights: a 5 x 3 softbox high at the front left, tilted towards the room (chapter 6), and a
-- dim warm point lamp at the front right (chapter 2), whose shadows stay hard.
local softbox = gr.area_light{position = {-6.0, 10.5, 7.0}, colour = {1.0, 0.98, 0.93},
                              size = {5, 3}, normal = {0.5, -1, -0.5}, left = {1, 0, -1}}
local lamp = gr.light({9, 7, 7}, {0.35, 0.27, 0.18}, {1, 0, 0})

gr.render(scene, 'showcase.png', 640, 400,
          {0, 2.8, 10.5}, {0, -0.115, -1}, {0, 1, 0}, 42,
          {0.12, 0.12, 0.14}, {softbox, lamp})
