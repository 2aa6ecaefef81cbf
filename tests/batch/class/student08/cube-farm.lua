-- batch-expect: ok
-- A4, current framework: a grid of cubes whose heights follow a sine wave, using the unit
-- cube's corner at the origin.
local root = gr.node('root')
for i = 0, 5 do
  for j = 0, 5 do
    local h = 0.3 + 0.25 * (1 + math.sin(i * 0.9 + j * 0.6))
    local c = gr.cube('c' .. i .. j)
    c:scale(0.8, h, 0.8)
    c:translate(i - 3, 0, -j)
    c:set_material(gr.material({0.2 + i * 0.12, 0.4, 0.9 - j * 0.12}, {0.3, 0.3, 0.3}, 25))
    root:add_child(c)
  end
end
gr.render(root, 'cube-farm.png', 160, 120, {0, 4, 5}, {0, -0.7, -1}, {0, 1, 0}, 50,
          {0.25, 0.25, 0.25}, {gr.light({-4, 8, 4}, {0.9, 0.9, 0.9}, {1, 0, 0})})
