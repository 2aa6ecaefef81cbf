-- Material calls raybook does not know, from other courses: each stand-in is a diffuse material
-- whose kd is the call's first colour (a table of 3 numbers from 0 to 1, or a field kd, colour,
-- ...); a call with no colour is magenta. Left to right: red, blue, green, magenta.
-- expect-error: unknown-materials.lua:12: gr.phong_material is not a raybook call
-- expect-stderr: rt: warning: unknown-materials.lua:12: gr.phong_material: --lenient stands in a diffuse material whose kd is argument 1 {0.9, 0.1, 0.1}, its first colour
-- expect-stderr: rt: warning: unknown-materials.lua:13: gr.glass: --lenient stands in a diffuse material whose kd is argument 2 {0.1, 0.1, 0.9}, its first colour
-- expect-stderr: rt: warning: unknown-materials.lua:15: gr.texture_material: --lenient stands in a magenta material (no argument is a colour)
-- expect-red: 0.1 0.4 0.25 0.6
-- expect-blue: 0.33 0.4 0.45 0.6
-- expect-green: 0.55 0.4 0.67 0.6
-- expect-magenta: 0.75 0.4 0.9 0.6
local red = gr.phong_material({0.9, 0.1, 0.1}, {0.5, 0.5, 0.5}, 20)
local blue = gr.glass(1.5, {0.1, 0.1, 0.9})
local green = gr.metal_mat{colour = {0.1, 0.8, 0.1}, roughness = 0.2}
local unknown = gr.texture_material('wood.png', 2)
root = gr.node('root')
for i, m in ipairs({red, blue, green, unknown}) do
  local s = gr.sphere('s' .. i)
  s:translate(2.5 * i - 6.25, 0, 0)
  s:set_material(m)
  root:add_child(s)
end
gr.render(root, 'out.png', 64, 32, {0, 0, 12}, {0, 0, -1}, {0, 1, 0}, 30, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 12}, {0.9, 0.9, 0.9}, {1, 0, 0})})
