-- batch-expect: timed out
-- Merely slow, not broken: a 2000x2000 image of 400 balls under 1024 lights takes far longer
-- than the few seconds the batch test allows each scene, so the batch must stop it. (With 64
-- lights a quiet 2-core machine finished it in under 5 s, and the test failed there.)
local root = gr.node('root')
local white = gr.material({0.8, 0.8, 0.8}, {0.5, 0.5, 0.5}, 30)
for i = 0, 19 do
  for j = 0, 19 do
    local s = gr.nh_sphere('star', {i - 9.5, j - 9.5, -20}, 0.45)
    s:set_material(white)
    root:add_child(s)
  end
end
local lights = {}
for k = 1, 1024 do
  lights[k] = gr.light({math.cos(k) * 10, math.sin(k) * 10, 5}, {0.00125, 0.00125, 0.00125}, {1, 0, 0})
end
gr.render(root, 'stars.png', 2000, 2000, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 60,
          {0.1, 0.1, 0.1}, lights)
