-- rt-stats: instances +26$
-- rt-stats: [^0-9]592 triangles
-- macho-cows.lua: the more macho version of simple-cows.lua, in the spirit of the CS488 A4
-- sample: the cows are a polyhedral cow model (scenes/assets/cow.obj, 347 faces written as
-- triangles, quads and hexagons), loaded once and instanced as a herd of seven, inside a ring
-- of stone arches that is itself one arch instanced six times.
--
-- Run it from any folder, e.g. from the repository root:  ./rt scenes/a4/macho-cows.lua   (writes macho-cows.png)

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
for _, x in ipairs({-2.0, 1.2}) do
  local pillar = gr.cube('pillar')
  pillar:scale(0.8, 4, 0.8)
  pillar:translate(x, 0, -0.4)
  pillar:set_material(stone)
  arc:add_child(pillar)
end
lintel = gr.cube('lintel')
lintel:scale(4.6, 0.8, 1.0)
lintel:translate(-2.3, 4, -0.5)
lintel:set_material(stone)
arc:add_child(lintel)

-- A ring of six arches, radius 11, each turned to face the centre.
henge = gr.node('henge')
for i = 0, 5 do
  local place = gr.node('arc' .. i)
  place:translate(0, 0, 11)
  place:rotate('y', 60 * i + 30)
  place:add_child(arc)
  henge:add_child(place)
end
scene:add_child(henge)

-- Two mesh nodes, one per hide, name the same file: raybook reads it once and both share it.
-- Each is then instanced several times. The herd: position, heading (degrees about y), size,
-- cow.
brown_cow = gr.mesh('brown_cow', 'cow.obj')
brown_cow:set_material(hide)
black_cow = gr.mesh('black_cow', 'cow.obj')
black_cow:set_material(black)
herd = {
  {{0.0, 0, 3.0},   -20, 1.6, brown_cow},
  {{-3.8, 0, 0.5},   35, 1.4, brown_cow},
  {{3.6, 0, -0.5},  160, 1.5, black_cow},
  {{-1.5, 0, -3.5},  80, 1.3, brown_cow},
  {{2.0, 0, -5.5}, -120, 1.2, brown_cow},
  {{-5.5, 0, -5.0}, 10, 1.1, black_cow},
  {{5.8, 0, 4.0},  -150, 1.0, brown_cow},
}
for i, c in ipairs(herd) do
  local position, heading, size, model = table.unpack(c)
  local copy = gr.node('cow' .. i)
  copy:scale(size, size, size)
  copy:rotate('y', heading)
  copy:translate(table.unpack(position))
  copy:add_child(model)
  scene:add_child(copy)
end

sun  = gr.light({-20, 30, 25}, {0.8, 0.8, 0.8}, {1, 0, 0})
fill = gr.light({25, 10, 20}, {0.3, 0.3, 0.35}, {1, 0, 0})

gr.render(scene, 'macho-cows.png', 400, 260,
          {0, 9, 20}, {0, -0.42, -1}, {0, 1, 0}, 50,
          {0.35, 0.35, 0.35}, {sun, fill})
