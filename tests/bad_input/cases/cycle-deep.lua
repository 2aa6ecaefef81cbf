-- A cycle through a chain of ten nodes, closed at the bottom.
-- expect: adding 'n1' under 'n10' would make a cycle
local first = gr.node('n1')
local last = first
for i = 2, 10 do
  local n = gr.node('n' .. i)
  last:add_child(n)
  last = n
end
last:add_child(first) --!
