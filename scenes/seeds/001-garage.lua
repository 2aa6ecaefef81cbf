-- Seed 001, "Distributed Raytracer": a car in a white garage, on a platform surrounded by
-- water. Written in seed 001's own dialect:
--   gr.phongMat(kd, ks, shininess, reflectivity, glossiness)
--   gr.transMat(kd, indexOfRefraction, transparency, scatter)
--   gr.light(position, colour, falloff, {length, width}, normal, left)   (a rectangle)
--   gr.render(<the ten A4 arguments>, aa, ss, dist, {apertureSize, focalLength, dof})
-- raybook reads glossiness and scatter as the radius of chapter 7's fuzz sphere.
--
-- Seed 001 was written for the pre-2015 course framework, which post-multiplies transforms:
-- each node lists its transforms in reverse, as 'translate, then scale' for a wall that is
-- scaled first and then moved into place. raybook recognises the era from seed 001's calls
-- (gr.phongMat, gr.transMat, the 6-argument gr.light and the 14-argument gr.render) and says
-- so on stderr; no flag is needed.
--
-- Chapters used: 1-3, 4 (reflectivity), 5 (gr.transMat), 6 (the rectangular light and ss),
-- 7 (glossiness, scatter and dist: the epoxy floor and the translucent water), 8 (aa),
-- 11 (ripples on the water: seed 001's objective 4, which it left undone), 13 (gr.render's
-- 14th argument, {aperture, focalLength, dof}), 14 (node:csg cuts the wheel arches) and
-- 15 (gr.cyllinder: wheels, hub caps and headlamps; gr.cone: the lamp shades). gr.cyllinder is
-- seed 001's own spelling, so it too marks the scene as pre-2015 (rt says "era: pre-2015
-- framework" on stderr).
-- Chapters 9, 10 and 12 are not used: no meshes, textures or tone map in seed 001's report.
-- Parts of the seed's scene that wait for later chapters: none (seed 001 named photon mapping,
-- chapter 16, only as future work). The seed's car mesh from the web is not in raybook; a car of
-- boxes, cylinders and CSG stands in.

-- ---- Materials (seed 001's calls) ------------------------------------------------------------
local white     = gr.phongMat({0.85, 0.85, 0.83}, {0.1, 0.1, 0.1}, 10, 0, 0)
-- An epoxy garage floor: a faint, blurred reflection.
local epoxy     = gr.phongMat({0.55, 0.56, 0.58}, {0.3, 0.3, 0.3}, 40, 0.25, 0.15)
local doorGrey  = gr.phongMat({0.6, 0.62, 0.65}, {0.2, 0.2, 0.2}, 20, 0, 0)
local stone     = gr.phongMat({0.75, 0.72, 0.66}, {0.1, 0.1, 0.1}, 10, 0, 0)
local poolTile  = gr.phongMat({0.15, 0.4, 0.55}, {0.3, 0.3, 0.3}, 40, 0, 0)
-- Clear-coated car paint: a sharp mirror reflection on a red Phong base.
local paint     = gr.phongMat({0.7, 0.04, 0.03}, {0.8, 0.8, 0.8}, 120, 0.25, 0)
local chrome    = gr.phongMat({0.05, 0.05, 0.05}, {0.9, 0.9, 0.9}, 200, 0.8, 0)
local rubber    = gr.phongMat({0.04, 0.04, 0.04}, {0.15, 0.15, 0.15}, 8, 0, 0)
local seat      = gr.phongMat({0.25, 0.18, 0.12}, {0.1, 0.1, 0.1}, 10, 0, 0)
-- Tinted windows, clear headlamps, and water (mostly transparent, tinted blue-green).
local tinted    = gr.transMat({0.05, 0.06, 0.08}, 1.5, 0.75, 0)
local lampGlass = gr.transMat({0.9, 0.9, 0.8}, 1.5, 0.9, 0)
-- The water is translucent: its scatter blurs what is seen through it (chapter 7), and
-- ripples from two drops tilt its surface (chapter 11, raybook's set_bump: seed 001 documented
-- no bump call).
local water     = gr.transMat({0.05, 0.25, 0.3}, 1.33, 0.8, 0.04)
water:set_bump{pattern = 'ripples', strength = 0.004, wavelength = 0.04,
               centres = {{0.2, 1, 0.8}, {0.85, 1, 0.2}}}

local root = gr.node('root')

--- A box from corner lo to corner hi under `parent`.
local function box(parent, name, lo, hi, material)
  local b = gr.cube(name)
  b:translate(lo[1], lo[2], lo[3])
  b:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  b:set_material(material)
  parent:add_child(b)
  return b
end

--- A cylinder (seed 001's gr.cyllinder, chapter 15) with centre c, radius r and length len along z.
local function wheel(parent, name, c, r, len, material)
  local w = gr.cyllinder(name)
  w:translate(c[1], c[2], c[3])
  w:rotate('x', 90)
  w:scale(r, len / 2, r)
  w:set_material(material)
  parent:add_child(w)
  return w
end

--- An ellipsoid with centre c and radii r under `parent`.
local function ellipsoid(parent, name, c, r, material)
  local s = gr.sphere(name)
  s:translate(c[1], c[2], c[3])
  s:scale(r[1], r[2], r[3])
  s:set_material(material)
  parent:add_child(s)
  return s
end

-- ---- The garage ----------------------------------------------------------------------------
-- The floor has a pool at x in [-4, 4], z in [-8, -2]; the platform stands in it.
box(root, 'floor front', {-6, -0.6, -2}, {6, 0, 3}, epoxy)
box(root, 'floor back',  {-6, -0.6, -10}, {6, 0, -8}, epoxy)
box(root, 'floor left',  {-6, -0.6, -8}, {-4, 0, -2}, epoxy)
box(root, 'floor right', {4, -0.6, -8}, {6, 0, -2}, epoxy)
box(root, 'pool floor',  {-4, -0.7, -8}, {4, -0.6, -2}, poolTile)
-- The water overlaps the pool's floor and walls a little, so that they lie inside it.
box(root, 'water', {-4.02, -0.65, -8.02}, {4.02, -0.12, -1.98}, water)
box(root, 'platform', {-2.8, -0.6, -6.4}, {2.8, 0.2, -3.6}, stone)

box(root, 'back wall',  {-6, 0, -10.2}, {6, 4, -10}, white)
box(root, 'left wall',  {-6.2, 0, -10}, {-6, 4, 3}, white)
box(root, 'right wall', {6, 0, -10}, {6.2, 4, 3}, white)
box(root, 'ceiling',    {-6, 4, -10}, {6, 4.2, 3}, white)
-- A sectional garage door in the back wall.
for i = 0, 5 do
  box(root, 'door panel', {-2.5, 0.05 + i * 0.5, -10}, {2.5, 0.5 + i * 0.5, -9.95}, doorGrey)
end

-- ---- The car (x: front to back, y: up, z: side to side) -------------------------------------
local car = gr.node('car')
local body = box(car, 'body', {-2.0, 0.3, -0.9}, {2.0, 0.85, 0.9}, paint)
box(car, 'bonnet', {0.9, 0.85, -0.85}, {2.0, 0.95, 0.85}, paint)
box(car, 'cabin', {-1.2, 0.85, -0.8}, {0.9, 1.38, 0.8}, tinted)
box(car, 'roof', {-1.25, 1.38, -0.82}, {0.75, 1.48, 0.82}, paint)
box(car, 'front seat', {-0.3, 0.85, -0.6}, {0.2, 1.25, 0.6}, seat)
box(car, 'back seat', {-1.15, 0.85, -0.6}, {-0.7, 1.2, 0.6}, seat)
box(car, 'front bumper', {2.0, 0.3, -0.95}, {2.12, 0.48, 0.95}, chrome)
box(car, 'rear bumper', {-2.12, 0.3, -0.95}, {-2.0, 0.48, 0.95}, chrome)
-- Headlamps: short glass cylinders, whose caps refract (seed 001 showed them black).
for _, z in ipairs({-0.6, 0.6}) do
  local lamp = gr.cyllinder('headlamp')
  lamp:translate(2.0, 0.68, z)
  lamp:rotate('z', 90)
  lamp:scale(0.13, 0.05, 0.13)
  lamp:set_material(lampGlass)
  car:add_child(lamp)
end
for _, x in ipairs({-1.3, 1.3}) do
  for _, side in ipairs({-1, 1}) do
    wheel(car, 'tyre', {x, 0.38, side * 0.9}, 0.38, 0.32, rubber)
    wheel(car, 'hub cap', {x, 0.38, side * 1.0}, 0.2, 0.14, chrome)
  end
end
-- Wheel arches cut out of the body with seed 001's node:csg (chapter 14); operand B is a
-- group of two ellipsoids, the hierarchy seed 001 could not take.
local arches = gr.node('arches')
for _, x in ipairs({-1.3, 1.3}) do
  ellipsoid(arches, 'arch', {x, 0.38, 0}, {0.47, 0.47, 1.5}, paint)
end
body:csg(arches, 'd')
car:translate(0, 0.2, -5)
car:rotate('y', -35)
root:add_child(car)

-- ---- Lights: a rectangular ceiling panel (seed 001's six-argument gr.light) and a fill -------
local panel = gr.light({0, 3.95, -5}, {0.85, 0.85, 0.8}, {1, 0, 0},
                       {4, 2}, {0, -1, 0}, {1, 0, 0})
local fill  = gr.light({4, 3, 2}, {0.25, 0.25, 0.28}, {1, 0, 0})
-- Two lamp shades under the ceiling: seed 001's gr.cone (chapter 15).
for _, x in ipairs({-3.5, 3.5}) do
  local shade = gr.cone('lamp shade')
  shade:translate(x, 3.6, -5)
  shade:scale(0.35, 0.25, 0.35)
  shade:set_material(white)
  root:add_child(shade)
end

-- aa = 1 (2 x 2 supersampling, chapter 8), ss = 3 (3 x 3 shadow rays per light), dist = 2 (2 x 2 glossy rays),
-- and the depth of field (chapter 13): a square aperture of side 0.1 focused at 7.7, the car's
-- distance, with dof = 3 (3 x 3 lens samples, paired with the pixel's rays).
gr.render(root, '001-garage.png', 320, 240,
          {4.2, 2.3, 1.2}, {-4.2, -1.7, -6.2}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {panel, fill},
          1, 3, 2, {0.1, 7.7, 3})
