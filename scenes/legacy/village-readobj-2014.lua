-- rt-era: legacy
-- rt-same-as: equivalent.lua
-- village-readobj-2014.lua: the village of village-2012.lua once more, written the way a
-- 2014 course scene would read a model: through the readobj.lua helper (which uses
-- string.gfind, a Lua 5.0/5.1 name). The sandbox has no io, so the OBJ text is in this file.
-- rt tells its era from string.gfind, the table mesh and unpack, so no flag is needed:
--   ./build/rt_ch3 scenes/legacy/village-readobj-2014.lua
-- It must give exactly the picture of equivalent.lua, village.png.

require('readobj')

-- The same house as scenes/assets/house.obj.
house_obj = [[
# house: a box with a gabled roof
v -0.5 0 -0.7
v 0.5 0 -0.7
v 0.5 0 0.7
v -0.5 0 0.7
v -0.5 0.8 -0.7
v 0.5 0.8 -0.7
v 0.5 0.8 0.7
v -0.5 0.8 0.7
v 0 1.3 -0.7
v 0 1.3 0.7
f 1 2 3 4
f 1 5 9 6 2
f 4 3 7 10 8
f 2 6 7 3
f 1 4 8 5
f 6 9 10 7
f 5 8 10 9
]]

grass  = gr.material({0.3, 0.6, 0.25}, {0.0, 0.0, 0.0}, 0)
wall   = gr.material({0.9, 0.85, 0.7}, {0.2, 0.2, 0.2}, 10)
red    = gr.material({0.75, 0.2, 0.15}, {0.3, 0.3, 0.3}, 20)
wood   = gr.material({0.45, 0.3, 0.15}, {0.1, 0.1, 0.1}, 5)
leaves = gr.material({0.15, 0.5, 0.15}, {0.2, 0.3, 0.2}, 15)
sail   = gr.material({0.95, 0.95, 0.9}, {0.4, 0.4, 0.4}, 30)
water  = gr.material({0.2, 0.4, 0.8}, {0.8, 0.8, 0.8}, 100)

-- Helpers in the old style: a shape with its transforms listed last-applied first.
function placed(node, mat, ...)
  for _, t in ipairs(arg or {...}) do
    local kind = t[1]
    if kind == 't' then node:translate(t[2], t[3], t[4])
    elseif kind == 's' then node:scale(t[2], t[3], t[4])
    else node:rotate(t[2], t[3]) end
  end
  if mat then node:set_material(mat) end
  return node
end

root = gr.node('root')
root:add_child(placed(gr.nh_box('ground', {-20, -40, -30}, 40), grass))
root:add_child(placed(gr.sphere('pond'), water, {'t', 2.5, 0, 2.0}, {'s', 2.2, 0.05, 1.4}))

house = gr.mesh('house', readobj(house_obj))
house:set_material(wall)

houses = {{{-3.5, 0, -1.0}, 20, 1.5}, {{-1.2, 0, -3.5}, -10, 1.25}, {{2.2, 0, -4.0}, 35, 1.0}}
for i = 1, #houses do
  local pos, turn, size = unpack(houses[i])
  local place = placed(gr.node('house' .. i), nil,
                       {'t', unpack(pos)}, {'r', 'y', turn}, {'s', size, size, size})
  place:add_child(house)
  root:add_child(place)
end

tree = gr.node('tree')
tree:add_child(placed(gr.cube('trunk'), wood, {'t', -0.1, 0, -0.1}, {'s', 0.2, 1.0, 0.2}))
tree:add_child(placed(gr.sphere('crown'), leaves, {'t', 0, 1.5, 0}, {'s', 0.6, 0.8, 0.6}))
trees = {{-5.5, -4.5, 1.25}, {0.5, -6.5, 1.0}, {6.8, 0.5, 1.5}, {-4.8, 2.5, 0.75}}
for i = 1, #trees do
  local x, z, size = unpack(trees[i])
  local place = placed(gr.node('tree' .. i), nil, {'t', x, 0, z}, {'s', size, size, size})
  place:add_child(tree)
  root:add_child(place)
end

mill = placed(gr.node('mill'), nil, {'t', 4.5, 0, -8.0}, {'r', 'y', -30})
root:add_child(mill)
mill:add_child(placed(gr.cube('tower'), wall, {'t', -0.6, 0, -0.6}, {'s', 1.2, 3.0, 1.2}))
mill:add_child(placed(gr.sphere('cap'), red, {'t', 0, 3.0, 0}, {'s', 0.9, 0.6, 0.9}))
hub = placed(gr.joint('hub', {0, 0, 0}, {-180, 20, 180}), nil, {'t', 0, 2.7, 0.75}, {'r', 'z', 20})
mill:add_child(hub)
blade = placed(gr.cube('blade'), sail, {'t', -0.175, 0.1, 0}, {'s', 0.35, 1.8, 0.05})
for k = 0, 3 do
  local arm = placed(gr.node('arm' .. k), nil, {'r', 'z', 90 * k})
  arm:add_child(blade)
  hub:add_child(arm)
end

sun  = gr.light({-15, 20, 15}, {0.8, 0.8, 0.75}, {1, 0, 0})
fill = gr.light({10, 6, 12}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(root, 'village.png', 400, 250,
          {0, 6, 12}, {0, -0.45, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {sun, fill})
