-- rt-era: legacy
-- rt-same-as: equivalent.lua
-- village-io-2012.lua: the village of village-2012.lua, with its house read from an OBJ file
-- the way pre-2015 course scenes did: the readobj helper (readobj-io.lua here) opens the file
-- with io.open and walks it with file:lines() and string.gfind. raybook's sandbox has a
-- read-only io for this; it reads files under the scene's folder and the --assets folders
-- only, so the OBJ (house.obj, a copy of ../assets/house.obj) sits beside this file.
-- rt tells its era from string.gfind, the table mesh and unpack, so no flag is needed:
--   ./build/rt_ch3 scenes/legacy/village-io-2012.lua
-- It must give exactly the picture of equivalent.lua, village.png.

require('readobj-io')

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
pond:translate(2.5, 0, 2.0)
pond:scale(2.2, 0.05, 1.4)
pond:set_material(water)
root:add_child(pond)

-- The house, read from house.obj beside this file by readobj-io.lua's io.open and file:lines().
house = gr.mesh('house', readobj('house.obj'))
house:set_material(wall)

houses = {{{-3.5, 0, -1.0}, 20, 1.5}, {{-1.2, 0, -3.5}, -10, 1.25}, {{2.2, 0, -4.0}, 35, 1.0}}
for i = 1, #houses do
  local pos, turn, size = unpack(houses[i])
  local place = gr.node('house' .. i)
  place:translate(unpack(pos))
  place:rotate('y', turn)
  place:scale(size, size, size)
  place:add_child(house)
  root:add_child(place)
end

tree = gr.node('tree')
trunk = gr.cube('trunk')
trunk:translate(-0.1, 0, -0.1)
trunk:scale(0.2, 1.0, 0.2)
trunk:set_material(wood)
tree:add_child(trunk)
crown = gr.sphere('crown')
crown:translate(0, 1.5, 0)
crown:scale(0.6, 0.8, 0.6)
crown:set_material(leaves)
tree:add_child(crown)
trees = {{-5.5, -4.5, 1.25}, {0.5, -6.5, 1.0}, {6.8, 0.5, 1.5}, {-4.8, 2.5, 0.75}}
for i = 1, #trees do
  local x, z, size = unpack(trees[i])
  local place = gr.node('tree' .. i)
  place:translate(x, 0, z)
  place:scale(size, size, size)
  place:add_child(tree)
  root:add_child(place)
end

mill = gr.node('mill')
mill:translate(4.5, 0, -8.0)
mill:rotate('y', -30)
root:add_child(mill)
tower = gr.cube('tower')
tower:translate(-0.6, 0, -0.6)
tower:scale(1.2, 3.0, 1.2)
tower:set_material(wall)
mill:add_child(tower)
cap = gr.sphere('cap')
cap:translate(0, 3.0, 0)
cap:scale(0.9, 0.6, 0.9)
cap:set_material(red)
mill:add_child(cap)
hub = gr.joint('hub', {0, 0, 0}, {-180, 20, 180})
hub:translate(0, 2.7, 0.75)
hub:rotate('z', 20)
mill:add_child(hub)
blade = gr.cube('blade')
blade:translate(-0.175, 0.1, 0)
blade:scale(0.35, 1.8, 0.05)
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
