-- Found while reducing a fuzzing timeout (tests/fuzz/regressions/lua_scene/
-- fuzz-timeout-recursive-arm.lua): building a chain bottom up (each new node becomes the
-- parent of the chain so far) made each add_child's cycle check walk the whole chain:
-- quadratic time that the Lua instruction limit did not see, so rt hung. The nodes the check
-- visits now count against that limit.
-- expect: node:add_child: the scene script ran more than
-- expect: counting the work of its calls
local n = gr.node('n')
for i = 1, 200000 do
  local p = gr.node('p')
  p:add_child(n) --!
  n = p
end
