-- Chapter 14: constructive solid geometry. Four solids on a floor, each made by combining
-- others along every ray:
--   * a red block with a ball bitten out of its corner (gr.difference): the bite's surface is
--     the blue ball's, its normal turned to face out of the block;
--   * a glass lens, the intersection of two spheres (gr.intersection), standing in front of a
--     striped card so its magnification shows;
--   * a hollow glass shell, a sphere minus a smaller one, with a yellow ball floating in the
--     hollow: the ray enters glass, leaves into the hollow, re-enters and leaves (the medium
--     stack of chapter 5 keeps count);
--   * a die: a cube rounded by intersecting it with a sphere, with pips subtracted, built with
--     seed 001's node:csg on a hierarchical operand (a group of pips). The die is rotated and
--     its operands are transformed nodes.
-- max_depth 8: every glass path is split in full (no random choice), so the render is exact.
gr.option('max_depth', 8)

local floorM = gr.material({0.75, 0.75, 0.7}, {0.1, 0.1, 0.1}, 10)
local red    = gr.material({0.8, 0.15, 0.1}, {0.5, 0.5, 0.5}, 40)
local blue   = gr.material({0.15, 0.3, 0.85}, {0.5, 0.5, 0.5}, 40)
local ivory  = gr.material({0.9, 0.88, 0.8}, {0.4, 0.4, 0.4}, 60)
local pipM   = gr.material({0.1, 0.1, 0.12}, {0.3, 0.3, 0.3}, 20)
local yellow = gr.material({0.9, 0.75, 0.1}, {0.4, 0.4, 0.4}, 40)
local stripeA = gr.material({0.1, 0.1, 0.1}, {0, 0, 0}, 1)
local stripeB = gr.material({0.9, 0.9, 0.9}, {0, 0, 0}, 1)
local glass  = gr.material{kd = {0.02, 0.02, 0.02}, ks = {0.6, 0.6, 0.6}, shininess = 120,
                           transparency = 0.95, ior = 1.5}

local root = gr.node('root')

local wallM = gr.material({0.45, 0.6, 0.8}, {0, 0, 0}, 1)
local wall = gr.cube('wall')
wall:scale(30, 12, 0.5)
wall:translate(-15, 0, -7)
wall:set_material(wallM)
root:add_child(wall)

local floor = gr.cube('floor')
floor:scale(16, 0.5, 12)
floor:translate(-8, -0.5, -9)
floor:set_material(floorM)
root:add_child(floor)

-- The bitten block.
local block = gr.cube('block')
block:scale(1.6, 1.6, 1.6)
block:set_material(red)
local bite = gr.nh_sphere('bite', {1.6, 1.6, 1.6}, 1.1)
bite:set_material(blue)
local bitten = gr.difference(block, bite, 'bitten block')
bitten:rotate('y', -20)
bitten:translate(-4.0, 0, -1.4)
root:add_child(bitten)

-- The lens: two unit spheres 1.6 apart; thickness 0.4, radius of its rim 0.6.
local s1 = gr.sphere('s1'); s1:translate(0, 0, 0.8)
local s2 = gr.sphere('s2'); s2:translate(0, 0, -0.8)
local lens = gr.intersection(s1, s2, 'lens')
lens:set_material(glass)
lens:scale(1.3, 1.3, 1.3)
lens:translate(-0.9, 0.85, 0.3)
root:add_child(lens)
for i = 0, 7 do
  local stripe = gr.cube('stripe' .. i)
  stripe:scale(0.2, 2.0, 0.05)
  stripe:translate(-2.5 + 0.2 * 2 * i, 0, -1.6)
  stripe:set_material(i % 2 == 0 and stripeA or stripeB)
  root:add_child(stripe)
  local gap = gr.cube('gap' .. i)
  gap:scale(0.2, 2.0, 0.05)
  gap:translate(-2.3 + 0.2 * 2 * i, 0, -1.6)
  gap:set_material(i % 2 == 0 and stripeB or stripeA)
  root:add_child(gap)
end

-- The hollow shell and the ball inside it.
local outer = gr.sphere('outer'); outer:scale(1.1, 1.1, 1.1)
local inner = gr.sphere('inner'); inner:scale(0.9, 0.9, 0.9)
local shell = gr.difference(outer, inner, 'shell')
shell:set_material(glass)
shell:translate(1.3, 1.1, -0.6)
root:add_child(shell)
local ball = gr.nh_sphere('ball', {1.3, 0.75, -0.6}, 0.3)
ball:set_material(yellow)
root:add_child(ball)

-- The die, seed 001's way: die:csg(other, op) turns die into the result in place.
local die = gr.cube('die')
die:translate(-0.5, -0.5, -0.5)
die:set_material(ivory)
local round = gr.sphere('round'); round:scale(0.75, 0.75, 0.75)
die:csg(round, 'n')
local pips = gr.node('pips')
for _, p in ipairs({{0, 0, 0.5}, {0.25, 0.25, -0.5}, {-0.25, -0.25, -0.5},
                    {0.5, 0.25, 0.25}, {0.5, -0.25, -0.25}, {0.5, 0, 0}}) do
  local pip = gr.nh_sphere('pip', p, 0.12)
  pip:set_material(pipM)
  pips:add_child(pip)
end
die:csg(pips, 'd')
die:scale(1.5, 1.5, 1.5)
die:rotate('x', 35)
die:rotate('y', -40)
die:translate(3.7, 0.95, 0.4)
root:add_child(die)

local key = gr.light({-5, 9, 7}, {0.8, 0.8, 0.75}, {1, 0, 0})
local fill = gr.light({6, 5, 6}, {0.35, 0.35, 0.4}, {1, 0, 0})

gr.render(root, 'chapter14-csg.png', 256, 160,
          {0, 2.8, 7.5}, {0, -0.25, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {key, fill})
