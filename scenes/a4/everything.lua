-- rt-stats: instances +21$
-- rt-stats: [^0-9]56 triangles
-- everything.lua: one scene that uses every call of the CS488 A4 scene language and every
-- point of its semantics, laid out so that each can be checked by eye. Left to right:
--
--  1. gr.cube (the unit cube from (0,0,0) to (1,1,1)) beside cubeSq.obj, the same cube
--     written with quads; both get the same transforms, so they must look the same.
--  2. A plank: scale(3, 0.3, 0.3), then rotate('z', 40), then translate. Transforms apply in
--     the order written, so it is a straight bar tilted up to the right, resting on the floor
--     at its left end. (In the other order the bar would be sheared into a rhombus.)
--  3. A squashed sphere (non-uniform scale, then rotate 'x'): its highlight and shading need
--     normals transformed by the inverse transpose.
--  4. A planet: a geometry node with children. The moons are children of the planet sphere and
--     inherit its transform (scale 0.9): a moon translated by 1.9 sits 1.71 from the centre.
--     The planet hangs from a gr.joint, which acts as a plain transform node.
--  5. gr.nh_box, whose tuple is its minimum corner (it rests on the floor; a centred box would
--     sink halfway), and gr.nh_sphere resting beside it.
--  6. The dodecahedron twice: two gr.mesh nodes name the same file in the two forms raybook
--     accepts (relative to the working directory, and relative to this scene's folder), so
--     it is read once and shared. One copy is scaled non-uniformly.
--  7. faceforms.obj (an octahedron using every face form, negative indices and the skipped
--     statements) in front.
--  8. Instancing: one lamp-post subtree at the four corners of the floor.
--
-- Rotations use the axis names 'x', 'X', 'y', 'Y', 'z' and 'Z'.
--
-- Lights use every falloff term (c0, c1 and c2 all non-zero), the ambient term is set, the
-- view direction is not normalised and the up vector is not orthogonal to it. Two gr.render
-- calls: the second, from above, is requested after the scene changed (a moon moved, the
-- plank got a new material); the first image must not show those changes.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/everything.lua
-- (writes everything.png and everything-top.png)

red    = gr.material({0.85, 0.2, 0.15}, {0.7, 0.7, 0.7}, 50)
orange = gr.material({0.95, 0.55, 0.1}, {0.5, 0.5, 0.5}, 30)
green  = gr.material({0.2, 0.7, 0.3}, {0.4, 0.4, 0.4}, 25)
blue   = gr.material({0.2, 0.35, 0.9}, {0.6, 0.6, 0.6}, 80)
purple = gr.material({0.6, 0.3, 0.8}, {0.5, 0.5, 0.5}, 40)
gold   = gr.material({0.85, 0.7, 0.25}, {0.9, 0.8, 0.5}, 100)
grey   = gr.material({0.6, 0.6, 0.6}, {0.2, 0.2, 0.2}, 10)
white  = gr.material({0.9, 0.9, 0.85}, {0.3, 0.3, 0.3}, 20)
floorm = gr.material({0.55, 0.5, 0.45}, {0.0, 0.0, 0.0}, 1)

root = gr.node('root')

floor = gr.cube('floor')
floor:scale(17, 0.5, 10)
floor:translate(-8.5, -0.5, -5)
floor:set_material(floorm)
root:add_child(floor)

-- 1. gr.cube and the quad cube, with identical transforms apart from where they stand.
cube = gr.cube('cube')
cube:rotate('Y', 30)
cube:translate(-7.4, 0, -0.5)
cube:set_material(red)
root:add_child(cube)

quadcube = gr.mesh('quadcube', 'cubeSq.obj')  -- found in this scene's own folder
quadcube:rotate('Y', 30)
quadcube:translate(-5.9, 0, -0.5)
quadcube:set_material(red)
root:add_child(quadcube)

-- 2. The plank: scale, then rotate, then translate.
plank = gr.cube('plank')
plank:scale(3, 0.3, 0.3)
plank:rotate('z', 40)
plank:translate(-4.6, 0, 1.2)
plank:set_material(orange)
root:add_child(plank)

-- 3. A squashed, tilted sphere.
egg = gr.sphere('egg')
egg:scale(0.9, 0.45, 0.6)
egg:rotate('x', -35)
egg:translate(-1.2, 0.7, 2.2)
egg:set_material(blue)
root:add_child(egg)

-- 4. The planet and its moons, hanging from a joint.
arm = gr.joint('arm', {-45, 0, 45}, {-30, 0, 30})
arm:translate(0, 2.0, -1)
root:add_child(arm)
planet = gr.sphere('planet')
planet:scale(0.9, 0.9, 0.9)
planet:set_material(green)
arm:add_child(planet)
moon = gr.sphere('moon')
moon:scale(0.25, 0.25, 0.25)
moon:translate(1.9, 0, 0)   -- 1.9 x 0.9 = 1.71 from the planet's centre in the world
moon:set_material(white)
planet:add_child(moon)
moon2 = gr.sphere('moon2')
moon2:scale(0.18, 0.18, 0.18)
moon2:translate(0, 0, 1.9)
moon2:rotate('Z', 30)
moon2:rotate('y', -60)
moon2:set_material(grey)
planet:add_child(moon2)

-- 5. nh_box by its minimum corner, and nh_sphere by its centre and radius.
block = gr.nh_box('block', {1.6, 0, -0.2}, 1.2)
block:set_material(purple)
root:add_child(block)
ball = gr.nh_sphere('ball', {3.5, 0.6, 0.4}, 0.6)
ball:set_material(gold)
root:add_child(ball)

-- 6. The dodecahedron, named in two spellings ('dodeca.obj' and './dodeca.obj'): read once,
--    shared by both nodes.
dodeca1 = gr.mesh('dodeca1', 'dodeca.obj')
dodeca1:scale(0.45, 0.45, 0.45)
dodeca1:rotate('X', 20)
dodeca1:translate(5.3, 0.78, -0.8)
dodeca1:set_material(gold)
root:add_child(dodeca1)
dodeca2 = gr.mesh('dodeca2', './dodeca.obj')
dodeca2:scale(0.25, 0.6, 0.25)
dodeca2:rotate('z', -25)
dodeca2:translate(6.9, 1.0, 1.0)
dodeca2:set_material(blue)
root:add_child(dodeca2)

-- 7. The face-form octahedron.
octa = gr.mesh('octa', 'faceforms.obj')
octa:scale(0.6, 0.6, 0.6)
octa:rotate('y', 20)
octa:translate(1.5, 0.6, 3.0)
octa:set_material(red)
root:add_child(octa)

-- 8. One lamp post, instanced at the four corners of the floor.
lamppost = gr.node('lamppost')
post = gr.cube('post')
post:scale(0.16, 1.6, 0.16)
post:translate(-0.08, 0, -0.08)
post:set_material(grey)
lamppost:add_child(post)
lamp = gr.nh_sphere('lamp', {0, 1.8, 0}, 0.25)
lamp:set_material(white)
lamppost:add_child(lamp)
for i, at in ipairs({{-7, -4, 45}, {7, -4, -45}, {-7, 3.8, 45}, {7, 3.8, -45}}) do
  local place = gr.node('corner' .. i)
  place:rotate('y', at[3])
  place:translate(at[1], 0, at[2])
  place:add_child(lamppost)
  root:add_child(place)
end

-- Lights with every falloff term, and an ambient term.
key  = gr.light({-6, 12, 10}, {1.6, 1.55, 1.5}, {1.0, 0.02, 0.003})
fill = gr.light({10, 5, 8}, {0.9, 0.9, 1.1}, {0.7, 0.05, 0.005})

-- View (0,-5,-14) is not unit length; up (0,1,0.35) is not orthogonal to it.
gr.render(root, 'everything.png', 480, 270,
          {0, 6, 14}, {0, -5, -14}, {0, 1, 0.35}, 42,
          {0.25, 0.25, 0.25}, {key, fill})

-- Change the scene after the first gr.render: only the second image may show this.
moon:translate(0, 0, 2)
plank:set_material(green)

gr.render(root, 'everything-top.png', 480, 270,
          {0, 22, 4}, {0, -22, -4}, {0, 0, -1}, 40,
          {0.25, 0.25, 0.25}, {key, fill})
