-- rt-era: modern
-- equivalent.lua: the modern (Lua 5.4, current CS488 A4) form of the legacy village scenes
-- village-2012.lua, village-readobj-2014.lua and village-io-2012.lua in this folder. It must
-- render to exactly the same image as each of them, which rt renders as pre-2015 scenes
-- (tests/scenes/run_all.sh compares the PNG files byte for byte).
--
-- What differs from the legacy files:
--  * transforms are listed in the order they apply (the legacy files list them in reverse);
--  * table.unpack instead of unpack;
--  * the house comes from house.obj beside this file (1-based; the same polygons as
--    ../assets/house.obj) instead of Lua tables (0-based) or readobj.lua, so a copy of this
--    folder renders on its own.
-- Every node has at most two non-translation transforms, followed by at most one translation,
-- so the matrix products are exactly the same in either order of multiplication.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/legacy/equivalent.lua   (writes village.png)

grass  = gr.material({0.3, 0.6, 0.25}, {0.0, 0.0, 0.0}, 0)
wall   = gr.material({0.9, 0.85, 0.7}, {0.2, 0.2, 0.2}, 10)
red    = gr.material({0.75, 0.2, 0.15}, {0.3, 0.3, 0.3}, 20)
wood   = gr.material({0.45, 0.3, 0.15}, {0.1, 0.1, 0.1}, 5)
leaves = gr.material({0.15, 0.5, 0.15}, {0.2, 0.3, 0.2}, 15)
sail   = gr.material({0.95, 0.95, 0.9}, {0.4, 0.4, 0.4}, 30)
water  = gr.material({0.2, 0.4, 0.8}, {0.8, 0.8, 0.8}, 100)

root = gr.node('root')

ground = gr.nh_box('ground', {-20, -40, -30}, 40)
ground:set_material(grass)
root:add_child(ground)

pond = gr.sphere('pond')
pond:scale(2.2, 0.05, 1.4)
pond:translate(2.5, 0, 2.0)
pond:set_material(water)
root:add_child(pond)

-- The house mesh, painted as a whole.
house = gr.mesh('house', 'house.obj')
house:set_material(wall)

-- Three houses along a lane.
for i, h in ipairs({{{-3.5, 0, -1.0}, 20, 1.5}, {{-1.2, 0, -3.5}, -10, 1.25}, {{2.2, 0, -4.0}, 35, 1.0}}) do
  local pos, turn, size = h[1], h[2], h[3]
  local place = gr.node('house' .. i)
  place:scale(size, size, size)
  place:rotate('y', turn)
  place:translate(table.unpack(pos))
  place:add_child(house)
  root:add_child(place)
end

-- A tree: a trunk and a crown, instanced four times.
tree = gr.node('tree')
trunk = gr.cube('trunk')
trunk:scale(0.2, 1.0, 0.2)
trunk:translate(-0.1, 0, -0.1)
trunk:set_material(wood)
tree:add_child(trunk)
crown = gr.sphere('crown')
crown:scale(0.6, 0.8, 0.6)
crown:translate(0, 1.5, 0)
crown:set_material(leaves)
tree:add_child(crown)
for i, t in ipairs({{-5.5, -4.5, 1.25}, {0.5, -6.5, 1.0}, {6.8, 0.5, 1.5}, {-4.8, 2.5, 0.75}}) do
  local place = gr.node('tree' .. i)
  place:scale(t[3], t[3], t[3])
  place:translate(t[1], 0, t[2])
  place:add_child(tree)
  root:add_child(place)
end

-- A windmill: a tower, a cap, and a hub that holds four sails (one sail, instanced).
mill = gr.node('mill')
mill:rotate('y', -30)
mill:translate(4.5, 0, -8.0)
root:add_child(mill)
tower = gr.cube('tower')
tower:scale(1.2, 3.0, 1.2)
tower:translate(-0.6, 0, -0.6)
tower:set_material(wall)
mill:add_child(tower)
cap = gr.sphere('cap')
cap:scale(0.9, 0.6, 0.9)
cap:translate(0, 3.0, 0)
cap:set_material(red)
mill:add_child(cap)
hub = gr.joint('hub', {0, 0, 0}, {-180, 20, 180})
hub:rotate('z', 20)
hub:translate(0, 2.7, 0.75)
mill:add_child(hub)
blade = gr.cube('blade')
blade:scale(0.35, 1.8, 0.05)
blade:translate(-0.175, 0.1, 0)
blade:set_material(sail)
for k = 0, 3 do
  local arm = gr.node('arm' .. k)
  arm:rotate('z', 90 * k)
  arm:add_child(blade)
  hub:add_child(arm)
end

sun  = gr.light({-15, 20, 15}, {0.8, 0.8, 0.75}, {1, 0, 0})
fill = gr.light({10, 6, 12}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(root, 'village.png', 400, 250,
          {0, 6, 12}, {0, -0.45, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {sun, fill})
