-- A doubling DAG 24 levels deep (2^24 = 16.7 million sphere instances): just over the
-- instance limit. It must fail with an error in reasonable time and memory.
-- expect: node paths
local cur = gr.sphere('leaf')
for i = 1, 24 do
  local n = gr.node('level' .. i)
  n:add_child(cur)
  n:add_child(cur)
  cur = n
end
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(cur, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
