-- Found while reducing a fuzzing timeout (tests/fuzz/regressions/lua_scene/
-- fuzz-timeout-recursive-arm.lua): a chain of 200,000 nested nodes crashed rt even without a
-- gr.render call, when Lua freed the nodes at the end (each node's destructor freed its
-- child, recursively). Nodes now free their children without recursion.
-- expect: never calls gr.render
local n = gr.node('root')
for i = 1, 200000 do
  local c = gr.node('c')
  n:add_child(c)
  n = c
end
