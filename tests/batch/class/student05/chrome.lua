-- batch-expect: ok
-- Seed 000's dialect: a chrome ball ("reflect") between two matte ones, and an area light.
local chrome = gr.material({0.05, 0.05, 0.05}, {0.9, 0.9, 0.9}, 300, "reflect", 0.85)
local matte  = gr.material({0.7, 0.3, 0.5}, {0.1, 0.1, 0.1}, 5)
local floor  = gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1)

local root = gr.node('root')
local ground = gr.nh_box('ground', {-10, -21, -15}, 20)
ground:set_material(floor)
root:add_child(ground)
local mid = gr.nh_sphere('chrome', {0, 0, -3}, 1)
mid:set_material(chrome)
root:add_child(mid)
for _, x in ipairs({-2.3, 2.3}) do
  local s = gr.nh_sphere('matte', {x, -0.4, -3.5}, 0.6)
  s:set_material(matte)
  root:add_child(s)
end
local window = gr.area_light{position = {0, 5, -2}, colour = {0.9, 0.9, 0.9},
                             size = {3, 3}, normal = {0, -1, 0}, left = {1, 0, 0}, samples = 2}
gr.render(root, 'chrome.png', 160, 100,
          {0, 1, 3}, {0, -0.3, -1}, {0, 1, 0}, 55,
          {0.2, 0.2, 0.2}, {window})
