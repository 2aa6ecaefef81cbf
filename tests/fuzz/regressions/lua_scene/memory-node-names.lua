-- Found while fixing fuzzing's findings: the memory limit counted only what Lua allocates, and
-- a node's name is copied into C++, so nodes with long names could take all the machine's
-- memory under the 2 GiB limit. Nodes, materials and gr.render's copies count now.
-- (The fuzz harness's limit is 64 MiB, so this stops after a few nodes; ./rt's 2 GiB takes seconds.)
local name = string.rep('x', 1 << 24)
local keep = {}
for i = 1, 64 do
  keep[i] = gr.node(name)
end
