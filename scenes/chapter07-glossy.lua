-- Chapter 7: glossy reflection and translucency. Four metal spheres from a sharp mirror
-- (glossiness 0) to a rough, brushed look (glossiness 0.4) stand on a glossy floor that
-- reflects them as blurred shapes; a frosted-glass ball (chapter 5's refraction with a
-- glossiness) sits on the green block. Coloured blocks and a striped wall give the lobes
-- something to blur. Materials use raybook's named fields; gr.option sets the recursion limit
-- and the directions a glossy surface seen by the camera averages (16, the default; deeper
-- glossy bounces take one each; --glossy-samples=N overrides it).
gr.option('max_depth', 4)
gr.option('glossy_samples', 16)

local function metal(kd, glossiness)
  return gr.material{kd = kd, ks = {0.6, 0.6, 0.6}, shininess = 60, reflect = 0.75,
                     glossiness = glossiness}
end

local floorM = gr.material{kd = {0.25, 0.25, 0.28}, ks = {0.2, 0.2, 0.2}, shininess = 20,
                           reflect = 0.45, glossiness = 0.12}
local white  = gr.material{kd = {0.75, 0.75, 0.72}, ks = {0, 0, 0}, shininess = 1}
local dark   = gr.material{kd = {0.12, 0.14, 0.2}, ks = {0, 0, 0}, shininess = 1}
local red    = gr.material{kd = {0.8, 0.12, 0.1}, ks = {0.3, 0.3, 0.3}, shininess = 30}
local green  = gr.material{kd = {0.15, 0.6, 0.2}, ks = {0.3, 0.3, 0.3}, shininess = 30}
local blue   = gr.material{kd = {0.15, 0.25, 0.8}, ks = {0.3, 0.3, 0.3}, shininess = 30}

local scene = gr.node('root')

local floor = gr.cube('floor')
floor:scale(40, 1, 40)
floor:translate(-20, -2, -30)
floor:set_material(floorM)
scene:add_child(floor)

-- A wall of vertical stripes: sharp edges show how much each surface blurs.
for i = -10, 9 do
  local stripe = gr.cube('stripe' .. i)
  stripe:scale(0.6, 8, 0.5)
  stripe:translate(0.6 * i, -1, -9)
  stripe:set_material(i % 2 == 0 and white or dark)
  scene:add_child(stripe)
end

-- Four spheres of increasing glossiness, left to right.
local spheres = {
  {x = -3.45, kd = {0.05, 0.05, 0.06}, g = 0.0},   -- chrome: the chapter-4 mirror
  {x = -1.15, kd = {0.2, 0.14, 0.03}, g = 0.05},   -- polished gold
  {x = 1.15,  kd = {0.2, 0.08, 0.05}, g = 0.15},   -- satin copper
  {x = 3.45,  kd = {0.08, 0.08, 0.1}, g = 0.4},    -- brushed steel
}
for i, s in ipairs(spheres) do
  local ball = gr.nh_sphere('metal' .. i, {s.x, -0.2, -4}, 0.8)
  ball:set_material(metal(s.kd, s.g))
  scene:add_child(ball)
end

-- Behind the camera, a warm wall with dark panels: what the spheres' fronts reflect.
local warm = gr.material{kd = {0.7, 0.55, 0.4}, ks = {0, 0, 0}, shininess = 1}
local back = gr.cube('behind')
back:scale(40, 20, 1)
back:translate(-20, -1, 9)
back:set_material(warm)
scene:add_child(back)
for i = -3, 3 do
  local panel = gr.cube('panel' .. i)
  panel:scale(1.2, 3, 0.2)
  panel:translate(2.4 * i - 0.6, 0, 8.7)
  panel:set_material(dark)
  scene:add_child(panel)
end

-- Coloured blocks between the spheres, reflected in them and in the floor.
local blocks = {{-2.3, red}, {0.0, green}, {2.3, blue}}
for i, b in ipairs(blocks) do
  local block = gr.cube('block' .. i)
  block:scale(0.7, 1.5, 0.7)
  block:translate(b[1] - 0.35, -1, -6.2)
  block:set_material(b[2])
  scene:add_child(block)
end

-- Frosted glass (chapter 5's refraction, spread by the same lobe) on the green block: its
-- reflected and transmitted rays are both blurred, so the stripes seen through it dissolve.
local frosted = gr.material{kd = {0.05, 0.05, 0.06}, ks = {0.5, 0.5, 0.5}, shininess = 80,
                            ior = 1.5, transparency = 0.9, glossiness = 0.12}
local ball = gr.nh_sphere('frosted', {0, 1.15, -5.85}, 0.65)
ball:set_material(frosted)
scene:add_child(ball)

local key  = gr.light({-3, 7, 3}, {0.9, 0.9, 0.85}, {1, 0, 0})
local fill = gr.light({4, 3, 5}, {0.35, 0.35, 0.4}, {1, 0, 0})

gr.render(scene, 'chapter07-glossy.png', 256, 192,
          {0, 1.0, 4}, {0, -0.22, -1}, {0, 1, 0}, 50,
          {0.25, 0.25, 0.25}, {key, fill})
