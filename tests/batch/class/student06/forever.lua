-- batch-expect: error|timed out
-- Broken: an endless loop before gr.render. The sandbox stops it after 1e9 Lua
-- instructions (a few seconds); on a slow machine the batch's time limit may come first.
local root = gr.node('root')
local n = 0
while true do n = n + 1 end
gr.render(root, 'forever.png', 64, 48, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})
