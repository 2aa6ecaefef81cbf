-- hier.lua: a hierarchical CS488 A4 scene: a jointed puppet waving on a plinth. Every limb
-- hangs from a gr.joint (a plain transform node in A4); each joint's rotation moves the whole
-- subtree below it, through up to five levels of nested transforms. Transforms apply in the
-- order they are written: scale, then rotate, then translate.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/hier.lua   (writes hier.png)

skin  = gr.material({0.95, 0.75, 0.6}, {0.3, 0.3, 0.3}, 20)
shirt = gr.material({0.2, 0.45, 0.85}, {0.4, 0.4, 0.4}, 40)
pants = gr.material({0.25, 0.25, 0.3}, {0.2, 0.2, 0.2}, 10)
shoes = gr.material({0.45, 0.2, 0.1}, {0.5, 0.5, 0.5}, 60)
marble = gr.material({0.85, 0.85, 0.8}, {0.6, 0.6, 0.6}, 80)
floorm = gr.material({0.5, 0.45, 0.4}, {0.0, 0.0, 0.0}, 1)

-- A limb segment of the given length that hangs down (-y) from its pivot: the ellipsoid is
-- scaled first, then moved down by half its length, inside a node the joint can rotate.
function segment(name, length, radius, mat)
  local shape = gr.sphere(name .. '-shape')
  shape:scale(radius, length / 2, radius)
  shape:translate(0, -length / 2, 0)
  shape:set_material(mat)
  local node = gr.node(name)
  node:add_child(shape)
  return node
end

-- A joint at `offset` in its parent's frame holding `child`.
function joint_at(name, offset, child)
  local j = gr.joint(name, {-90, 0, 90}, {-90, 0, 90})
  j:add_child(child)
  j:translate(offset[1], offset[2], offset[3])
  return j
end

-- An arm: upper arm -> elbow -> forearm -> wrist -> hand.
function arm(side, shoulderZ, shoulderX, elbowX)
  local hand = gr.sphere(side .. '-hand')
  hand:scale(0.13, 0.16, 0.1)
  hand:translate(0, -0.12, 0)
  hand:set_material(skin)
  local forearm = segment(side .. '-forearm', 0.75, 0.11, skin)
  local wrist = joint_at(side .. '-wrist', {0, -0.75, 0}, hand)
  forearm:add_child(wrist)
  local elbow = joint_at(side .. '-elbow', {0, -0.8, 0}, forearm)
  elbow:rotate('x', elbowX)
  local upper = segment(side .. '-upper-arm', 0.8, 0.14, shirt)
  upper:add_child(elbow)
  local s = side == 'left' and 1 or -1
  local shoulder = joint_at(side .. '-shoulder', {0.62 * s, 0.55, 0}, upper)
  -- The shoulder joint itself turns: first about x (forward), then about z (out to the side).
  -- Undo the translation, rotate, redo it, so the rotation is about the joint.
  shoulder:translate(-0.62 * s, -0.55, 0)
  shoulder:rotate('x', shoulderX)
  shoulder:rotate('z', shoulderZ * s)
  shoulder:translate(0.62 * s, 0.55, 0)
  return shoulder
end

-- A leg: thigh -> knee -> shin -> ankle -> foot.
function leg(side, hipX, kneeX)
  local foot = gr.cube(side .. '-foot')
  foot:scale(0.22, 0.12, 0.4)
  foot:translate(-0.11, -0.12, -0.12)
  foot:set_material(shoes)
  local shin = segment(side .. '-shin', 0.95, 0.13, pants)
  shin:add_child(joint_at(side .. '-ankle', {0, -0.95, 0}, foot))
  local knee = joint_at(side .. '-knee', {0, -0.95, 0}, shin)
  knee:rotate('x', kneeX)
  local thigh = segment(side .. '-thigh', 0.95, 0.17, pants)
  thigh:add_child(knee)
  local s = side == 'left' and 1 or -1
  local hip = gr.joint(side .. '-hip', {-90, 0, 90}, {0, 0, 0})
  hip:add_child(thigh)
  hip:rotate('x', hipX)
  hip:translate(0.25 * s, -0.7, 0)
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
nose:scale(0.07, 0.07, 0.1)
nose:translate(0, 0, 0.33)
nose:set_material(skin)
head:add_child(nose)  -- a geometry node with a child
neck = joint_at('neck', {0, 1.25, 0}, head)
neck:rotate('y', 25)  -- look to the left; the nose follows
torso:add_child(neck)

torso:add_child(arm('left', 135, 0, -40))   -- waving
torso:add_child(arm('right', 25, 0, -35))
torso:add_child(leg('left', -20, 30))
torso:add_child(leg('right', 15, 5))

puppet = gr.node('puppet')
puppet:add_child(torso)
puppet:translate(0, 2.6, 0)
puppet:rotate('y', -20)
puppet:translate(0, 0.6, 0)  -- stand on the plinth

plinth = gr.cube('plinth')
plinth:scale(3, 0.6, 2)
plinth:translate(-1.5, 0, -1)
plinth:set_material(marble)

floor = gr.cube('floor')
floor:scale(30, 1, 30)
floor:translate(-15, -1, -15)
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
