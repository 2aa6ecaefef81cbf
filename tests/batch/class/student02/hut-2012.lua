-- batch-expect: ok
-- A pre-2015 course scene (Lua 5.1): a hut whose walls and roof are gr.mesh tables with
-- 0-based faces, a fence built with unpack, and transforms listed in reverse order.
local wall = gr.material({0.75, 0.6, 0.45}, {0.1, 0.1, 0.1}, 5)
local roof = gr.material({0.55, 0.15, 0.1}, {0.2, 0.2, 0.2}, 10)
local post = gr.material({0.35, 0.22, 0.1}, {0, 0, 0}, 1)

root = gr.node('root')

hut = gr.mesh('hut', {
  {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1},
  {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1},
}, {
  {0, 3, 2, 1}, {4, 5, 6, 7},
  {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7},
})
hut:set_material(wall)
root:add_child(hut)

top = gr.mesh('roof', {
  {-1.2, 1, -1.2}, {1.2, 1, -1.2}, {1.2, 1, 1.2}, {-1.2, 1, 1.2}, {0, 2, 0},
}, {
  {0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0},
})
top:set_material(roof)
root:add_child(top)

-- Fence posts: the old framework applies the last-listed transform first.
corners = {{-2.5, 0, 2}, {-1.5, 0, 2}, {-0.5, 0, 2}, {0.5, 0, 2}, {1.5, 0, 2}, {2.5, 0, 2}}
for i = 1, #corners do
  p = gr.cube('post' .. i)
  p:translate(unpack(corners[i]))
  p:scale(0.15, 0.8, 0.15)
  p:set_material(post)
  root:add_child(p)
end

gr.render(root, 'hut-2012.png', 160, 120,
          {3, 3, 8}, {-0.35, -0.3, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {gr.light({-6, 9, 8}, {0.9, 0.9, 0.9}, {1, 0, 0})})
