-- Found while reducing a fuzzing timeout (tests/fuzz/regressions/lua_scene/
-- fuzz-timeout-recursive-arm.lua): a chain of 20,000 nested nodes crashed rt at gr.render (a
-- stack overflow: flattening and copying the graph recurse once per level). Now gr.render
-- refuses a graph deeper than 1000 levels.
-- expect: levels deep, more than the limit of 1000
local root = gr.node('root')
local n = root
for i = 1, 20000 do
  local c = gr.node('c')
  n:add_child(c)
  n = c
end
n:add_child(gr.sphere('s'))
local l = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'deep.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {l}) --!
