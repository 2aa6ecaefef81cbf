-- batch-expect: ok
-- A 2013 course scene: a row of street lamps; positions are unpacked from a table and each
-- lamp's transforms are written last-applied-first, as the old framework expected.
lamp_positions = {{-3, 0, 0}, {0, 0, -2}, {3, 0, -4}}

iron = gr.material({0.2, 0.2, 0.22}, {0.6, 0.6, 0.6}, 40)
glow = gr.material({1.0, 0.9, 0.5}, {0.5, 0.5, 0.5}, 10)
road = gr.material({0.3, 0.3, 0.32}, {0.05, 0.05, 0.05}, 5)

root = gr.node('root')
street = gr.cube('street')
street:translate(-8, -1, -12)
street:scale(16, 1, 16)
street:set_material(road)
root:add_child(street)

for i, pos in ipairs(lamp_positions) do
  lamp = gr.node('lamp' .. i)
  lamp:translate(unpack(pos))
  pole = gr.cube('pole' .. i)
  pole:translate(-0.05, 0, -0.05)
  pole:scale(0.1, 2.5, 0.1)
  pole:set_material(iron)
  lamp:add_child(pole)
  bulb = gr.sphere('bulb' .. i)
  bulb:translate(0, 2.7, 0)
  bulb:scale(0.25, 0.25, 0.25)
  bulb:set_material(glow)
  lamp:add_child(bulb)
  root:add_child(lamp)
end

gr.render(root, 'lamps-2013.png', 160, 120,
          {0, 2, 8}, {0, -0.1, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.25}, {gr.light({2, 6, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})})
