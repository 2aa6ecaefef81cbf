-- A DAG that doubles at every level, 40 levels deep: 2^40 paths to the sphere. Building it
-- and flattening it must end with an error quickly, not hang or exhaust memory.
-- expect: node paths
local cur = gr.sphere('leaf')
for i = 1, 40 do
  local n = gr.node('level' .. i)
  n:add_child(cur)
  n:add_child(cur)
  cur = n
end
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(cur, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
