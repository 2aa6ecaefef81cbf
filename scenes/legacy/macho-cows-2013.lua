-- rt-era: legacy
-- rt-same-as: ../a4/macho-cows.lua
-- rt-stats: instances +26$
-- macho-cows-2013.lua: scenes/a4/macho-cows.lua, the herd of polyhedral cows in a ring of
-- arches, as a student had it before 2015 (Lua 5.1 course framework). rt tells its era from
-- string.gfind, the table mesh and unpack, so it needs no flag, and it must give exactly the
-- picture of ../a4/macho-cows.lua.
--
-- How it differs from the current sample:
--  * the cow is read the old way: the readobj helper (readobj-io.lua here, like the course's
--    readobj.lua) opens cow.obj with io.open, splits its lines with string.gfind and returns
--    Lua tables, vertices and faces counting from 0, for gr.mesh(name, vertices, faces).
--    raybook's sandbox lets io.open read only under the scene's folder, so cow.obj here is a
--    copy of ../a4/cow.obj;
--  * both hides are mesh nodes built from the same tables (the current sample names the same
--    .obj twice);
--  * transforms post-multiply, so each node lists its calls last-applied first: a cow copy
--    reads 'translate, rotate, scale' for "scale, then turn, then move";
--  * unpack is the Lua 5.1 global (table.unpack later).

require('readobj-io')

stone = gr.material({0.8, 0.7, 0.7}, {0.0, 0.0, 0.0}, 0)
grass = gr.material({0.1, 0.7, 0.1}, {0.0, 0.0, 0.0}, 0)
hide  = gr.material({0.84, 0.6, 0.53}, {0.3, 0.3, 0.3}, 20)
black = gr.material({0.2, 0.18, 0.17}, {0.4, 0.4, 0.4}, 30)

scene = gr.node('scene')

plane = gr.nh_box('plane', {-50, -100, -50}, 100)
plane:set_material(grass)
scene:add_child(plane)

-- One arch (two pillars and a lintel), 4.8 tall, centred on the origin, facing +z.
arc = gr.node('arc')
pillars = {-2.0, 1.2}
for i = 1, #pillars do
  local pillar = gr.cube('pillar')
  pillar:translate(pillars[i], 0, -0.4)
  pillar:scale(0.8, 4, 0.8)
  pillar:set_material(stone)
  arc:add_child(pillar)
end
lintel = gr.cube('lintel')
lintel:translate(-2.3, 4, -0.5)
lintel:scale(4.6, 0.8, 1.0)
lintel:set_material(stone)
arc:add_child(lintel)

-- A ring of six arches: each moved out to radius 11, then turned to its place.
henge = gr.node('henge')
for i = 0, 5 do
  local place = gr.node('arc' .. i)
  place:rotate('y', 60 * i + 30)
  place:translate(0, 0, 11)
  place:add_child(arc)
  henge:add_child(place)
end
scene:add_child(henge)

-- The cow model, read once into Lua tables; a brown and a black mesh node built from them.
cow_verts, cow_faces = readobj('cow.obj')
brown_cow = gr.mesh('brown_cow', cow_verts, cow_faces)
brown_cow:set_material(hide)
black_cow = gr.mesh('black_cow', cow_verts, cow_faces)
black_cow:set_material(black)

-- The herd: position, heading (degrees about y), size, cow.
herd = {
  {{0.0, 0, 3.0},   -20, 1.6, brown_cow},
  {{-3.8, 0, 0.5},   35, 1.4, brown_cow},
  {{3.6, 0, -0.5},  160, 1.5, black_cow},
  {{-1.5, 0, -3.5},  80, 1.3, brown_cow},
  {{2.0, 0, -5.5}, -120, 1.2, brown_cow},
  {{-5.5, 0, -5.0}, 10, 1.1, black_cow},
  {{5.8, 0, 4.0},  -150, 1.0, brown_cow},
}
for i = 1, #herd do
  local position, heading, size, model = unpack(herd[i])
  local copy = gr.node('cow' .. i)
  copy:translate(unpack(position))
  copy:rotate('y', heading)
  copy:scale(size, size, size)
  copy:add_child(model)
  scene:add_child(copy)
end

sun  = gr.light({-20, 30, 25}, {0.8, 0.8, 0.8}, {1, 0, 0})
fill = gr.light({25, 10, 20}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'macho-cows.png', 400, 260,
          {0, 9, 20}, {0, -0.42, -1}, {0, 1, 0}, 50,
          {0.35, 0.35, 0.35}, {sun, fill})
