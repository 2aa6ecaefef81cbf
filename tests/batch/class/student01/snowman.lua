-- batch-expect: ok
-- A4, current framework: a snowman built as a hierarchy, transforms in the order written.
local snow = gr.material({0.92, 0.93, 0.97}, {0.3, 0.3, 0.3}, 20)
local coal = gr.material({0.05, 0.05, 0.05}, {0.4, 0.4, 0.4}, 60)
local carrot = gr.material({0.95, 0.45, 0.1}, {0.2, 0.2, 0.2}, 10)

local root = gr.node('root')
local body = gr.node('body')
root:add_child(body)

local radii = {1.2, 0.85, 0.6}
local height = 0
for i, r in ipairs(radii) do
  local part = gr.sphere('part' .. i)
  part:scale(r, r, r)
  part:translate(0, height + r, 0)
  part:set_material(snow)
  body:add_child(part)
  height = height + 1.7 * r
end

for _, x in ipairs({-0.2, 0.2}) do
  local eye = gr.sphere('eye')
  eye:scale(0.07, 0.07, 0.07)
  eye:translate(x, 3.55, 0.55)
  eye:set_material(coal)
  body:add_child(eye)
end

local nose = gr.cube('nose')
nose:scale(0.1, 0.1, 0.5)
nose:translate(-0.05, 3.35, 0.5)
nose:set_material(carrot)
body:add_child(nose)

body:rotate('y', 15)

gr.render(root, 'snowman.png', 120, 120,
          {0, 2.5, 9}, {0, 0, -1}, {0, 1, 0}, 40,
          {0.3, 0.3, 0.35}, {gr.light({4, 8, 6}, {0.9, 0.9, 0.85}, {1, 0, 0})})
