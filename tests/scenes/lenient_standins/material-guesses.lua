-- raybook's gr.material with another course's shapes of arguments: a table where the shininess
-- belongs ({25}), a grey given as one number, and an RGBA colour. Under --lenient each is read
-- by the nearest shape, with a warning naming the guess: the spheres keep their colours.
-- expect-error: material-guesses.lua:12: gr.material: argument 3 (shininess) must be a number, got table
-- expect-stderr: rt: warning: material-guesses.lua:12: gr.material: argument 3 (shininess): --lenient read the table {25} as the number 25 (a table where a number belongs)
-- expect-stderr: rt: warning: material-guesses.lua:13: gr.material: argument 2 (ks): --lenient read the number 0.3 as {0.3, 0.3, 0.3} (a number where 3 belong)
-- expect-stderr: rt: warning: material-guesses.lua:14: gr.material: argument 1 (kd): --lenient read {0.1, 0.1, 0.9, 1} as its first 3 numbers {0.1, 0.1, 0.9} (an RGBA colour's alpha, or a w, left out)
-- expect-no-stderr: rt: --lenient ignored
-- expect-green: 0.15 0.35 0.35 0.65
-- expect-red: 0.4 0.35 0.6 0.65
-- expect-blue: 0.65 0.35 0.85 0.65
local green = gr.material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, {25})
local red = gr.material({0.9, 0.1, 0.1}, 0.3, 10)
local blue = gr.material({0.1, 0.1, 0.9, 1}, {0.2, 0.2, 0.2}, 10)
root = gr.node('root')
for i, m in ipairs({green, red, blue}) do
  local s = gr.sphere('s' .. i)
  s:translate(3 * i - 6, 0, 0)
  s:set_material(m)
  root:add_child(s)
end
gr.render(root, 'out.png', 64, 32, {0, 0, 12}, {0, 0, -1}, {0, 1, 0}, 30, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 12}, {0.9, 0.9, 0.9}, {1, 0, 0})})
