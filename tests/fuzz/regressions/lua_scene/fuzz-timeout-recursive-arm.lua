-- Found by fuzz_lua_scene (a 12 s timeout under ASan): hier-2013.lua mangled so that arm()
-- calls itself; each level made eight nodes, uncounted by the memory limit, until the Lua
-- stack overflowed. Nodes count against the memory limit now, so it stops early.
-- rt-era: legacy
-- rt-same-as: ../a4/hier.lua
-- hier-2013.lua: scenes/a4/hier.lua, the jointed puppet waving on a plinth, as a student had
-- it before 2015 (Lua 5.1 course framework). rt tells its era from unpack (the Lua 5.1 global
-- that later became table.unpack), so it needs no flag, and it must give exactly the picture
-- of ../a4/hier.lua.
--
-- The old framework post-multiplied transforms: each node lists its calls last-applied
-- first. 'translate, then scale' here means "scale, then translate"; a joint that is moved to
-- its place and then turned (in the current sample: translate, then rotate) is written
-- rotate first, then translate. So the joints are placed by the caller, after any rotation,
-- rather than inside the helper as in the current sample.

skin  = gr.material({0.95, 0.75, 0.6}, {0.3, 0.3, 0.3}, 20)
shirt = gr.material({0.2, 0.45, 0.85}, {0.4, 0.4, 0.4}, 40)
pants = gr.material({0.25, 0.25, 0.3}, {0.2, 0.2, 0.2}, 10)
shoes = gr.material({0.45, 0.2, 0.1}, {0.5, 0.5, 0.5}, 60)
marble = gr.material({0.85, 0.85, 0.8}, {0.6, 0.6, 0.6}, 80)
floorm = gr.material({0.5, 0.45, 0.4}, {0.0, 0.0, 0.0}, 1)

-- A limb segment hanging down from its pivot: an ellipsoid moved down by half its length
-- after it is stretched (listed in reverse: translate, then scale).
function segment(name, length, radius, mat)
  local shape = gr.sphere(name .. '-shape')
  shape:translate(0, -length / 2, 0)
  shape:scale(radius, length / 2, radius)
  shape:set_material(mat)
  local node = gr.node(name)
  node:add_child(shape)
  return node
end

-- A joint holding `child`; the caller turns it and then places it with place().
function joint(name, child)
  local j = gr.joint(name, {-90, 0, 90}, {-90, 0, 90})
  j:add_child(child)
  return j
end

-- The last call on a node is the first transform applied: moving a joint to `offset` in its
-- parent's frame comes last in the list when it happens first.
function place(node, offset)
  node:translate(unpack(offset))
  return node
end

-- An arm: upper arm -> elbow -> forearm -> wrist -> hand.
function arm(side, shoulderZ, shoulderX, elbowX)
  local hand = gr.sphere(side .. '-hand')
  hand:translate(0, -0.12, 0)
  hand:scale(0.13, 0.16, 0.1)
  hand:set_material(skin)
  local forearm = segment(side .. '-forearm', 0.75, 0.11, skin)
  forearm:add_child(place(joint(side .. '-wrist', hand), {0, -0.75, 0}))
  local elbow = joint(side .. '-elbow', forearm)
  elbow:rotate('x', elbowX)
  place(elbow, {0, -0.8, 0})
  lpe = gr.sphere('torso-shape')
torso_shape:scale(0.6, 0.85, 0.35)
torso_shape:set_material(shirt)
torso:add_child(torso_shape)

head = gr.sphere('head')
head:scale(0.33, 0.4, 0.33)
head:set_material(skin)
nose = gr.sphere('nose')
nose:translate(0, 0, 0.33)
nose:scale(0.07, 0.07, 0.1)
nose:set_material(skin)
head:add_child(nose)
neck = joint('neck', head)
neck:rotate('y', 25)  -- look to the left; the nose follows
place(neck, {0, 1.25, 0})
torso:add_child(neck)

torso:add_child(arm('left', 135, 0, -40))   -- waving
torso:add_child(arm('right', 25, 0, -35))
torso:add_child(leg('left', -20, 30))
torso:add_child(leg('right', 15, 5))

-- Lift the puppet by 2.6, turn it, and stand it on the plinth; listed in reverse.
puppet = gr.node('puppet')
puppet:add_child(torso)
puppet:translate(0, 0.6, 0)
puppet:rotate('y', -20)
puppet:translate(0, 2.6, 0)

plinth = _child(place(joint(side .. '-ankle', foot), {0, -0.95, 0}))
  local knee = joint(side .. '-knee', shin)
  knee:rotate('x', kneeX)
  place(knee, {0, -0.95, 0})
  local thigh = segment(side .. '-thigh', 0.95, 0.17, pants)
  thigh:add_child(knee)
  local s = side == 'left' and 1 or -1
  local hip = gr.joint(side .. '-hip', {-90, 0, 90}, {0, 0, 0})
  hip:add_child(thigh)
  hip:translate(0.25 * s, -0.7, 0)
  hip:rotate('x', hipX)
  return hip
end

-- The torso is the frame of the body; its ellipsoid is a child, so the torso's children do
-- not inherit the ellipsoid's non-uniform scale.
torso = gr.node('torso')
torso_shape = gr.sphere('torso-shape')
torso_shape:scale(0.6, 0.85, 0.35)
torso_shape:set_material(shirt)
torso:add_child(torso_shape)

head = gr.sphere('head')
head:scale(0.33, 0.4, 0.33)
head:set_material(skin)
nose = gr.sphere('nose')
nose:translate(0, 0, 0.33)
nose:scale(0.07, 0.07, 0.1)
nose:set_material(skin)
head:add_child(nose)
neck = joint('neck', head)
neck:rotate('y', 25)  -- look to the left; the nose follows
place(neck, {0, 1.25, 0})
torso:add_child(neck)

torso:add_child(arm('left', 135, 0, -40))   -- waving
torso:add_child(arm('right', 25, 0, -35))
torso:add_child(leg('left', -20, 30))
torso:add_child(leg('right', 15, 5))

-- Lift the puppet by 2.6, turn it, and stand it on the plinth; listed in reverse.
puppet = gr.node('puppet')
puppet:add_child(torso)
puppet:translate(0, 0.6, 0)
puppet:rotate('y', -20)
puppet:translate(0, 2.6, 0)

plinth = gr.cube('plinth')
plinth:translate(-1.5, 0, -1)
plinth:scale(3, 0.6, 2)
plinth:set_material(marble)

floor = gr.cube('floor')
floor:translate(-15, -1, -15)
floor:scale(30, 1, 30)
floor:set_material(floorm)

root = gr.node('root')
root:add_child(floor)
root:add_child(plinth)
root:add_child(puppet)

key  = gr.light({-6, 10, 9}, {0.85, 0.85, 0.8}, {1, 0, 0})
rim  = gr.light({7, 6, -4}, {0.4, 0.4, 0.5}, {1, 0, 0})

gr.render(root, 'hier.png', 256, 320,
          {0, 3.3, 10}, {0, -0.08, -1}, {0, 1, 0}, 40,
          {0.25, 0.25, 0.25}, {key, rim})
