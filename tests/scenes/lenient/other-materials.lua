-- The other material calls with arguments of another course: seed 001's gr.phongMat with a
-- name where its reflectivity goes, seed 002's gr.fancy_material with three of its seven
-- arguments, and raybook's gr.material{...} with a word for the shininess. Each sphere wears
-- the stand-in of its call: a diffuse material of the call's first colour, its green kd.
-- expect-error: other-materials.lua:12: gr.phongMat: argument 4 (reflectivity) must be a number, got string
-- expect-lenient: gr.phongMat (arguments raybook cannot read: argument 4 (reflectivity) must be a number, got string; a stand-in took its place), first at other-materials.lua:12
-- expect-lenient: gr.fancy_material (arguments raybook cannot read: expects 7 arguments (kd, ks, shininess, reflectivity, ior, transparency, glossiness), got 3; a stand-in took its place), first at other-materials.lua:13
-- expect-lenient: gr.material (arguments raybook cannot read: field 'shininess' must be a number, got string; a stand-in took its place), first at other-materials.lua:14
-- expect-green: 0.22 0.4 0.35 0.6
-- expect-green: 0.45 0.4 0.55 0.6
-- expect-green: 0.65 0.4 0.78 0.6
local a = gr.phongMat({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, 25, 'mirror', 0)
local b = gr.fancy_material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, 25)
local c = gr.material{kd = {0.1, 0.8, 0.1}, shininess = 'high'}
root = gr.node('root')
for i, m in ipairs({a, b, c}) do
  local s = gr.sphere('s' .. i)
  s:scale(1.5, 1.5, 1.5)
  s:translate(4 * (i - 2), 0, 0)
  s:set_material(m)
  root:add_child(s)
end
gr.render(root, 'out.png', 48, 36, {0, 0, 15}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 15}, {0.9, 0.9, 0.9}, {1, 0, 0})})
