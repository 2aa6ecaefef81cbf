-- Chapter 3: triangle meshes and the BVH. The low-resolution Stanford bunny (3,674 triangles,
-- loaded once) appears three times through instancing, on a box floor.
local floorMat = gr.material({0.55, 0.55, 0.5}, {0.0, 0.0, 0.0}, 1)
local clay     = gr.material({0.8, 0.55, 0.35}, {0.3, 0.3, 0.3}, 20)
local jade     = gr.material({0.25, 0.6, 0.35}, {0.5, 0.5, 0.5}, 60)

local scene = gr.node('root')

local floor = gr.nh_box('floor', {-10, -21, -15}, 20)
floor:set_material(floorMat)
scene:add_child(floor)

-- The bunny is about 9.7 units tall, its feet at y = 0 and centred on x = z = 0.
local bunny = gr.mesh('bunny', 'assets/bunny.obj')

local placements = {{-2.2, 30, clay}, {0, 0, jade}, {2.2, -30, clay}}
for i, p in ipairs(placements) do
  local holder = gr.node('bunny' .. i)
  holder:scale(0.2, 0.2, 0.2)
  holder:rotate('y', p[2])
  holder:translate(p[1], -1, 0)
  local inner = gr.node('material' .. i)
  inner:set_material(p[3])
  inner:add_child(bunny)
  holder:add_child(inner)
  scene:add_child(holder)
end

local key  = gr.light({-4, 6, 6}, {0.9, 0.9, 0.85}, {1, 0, 0})
local fill = gr.light({6, 3, 4}, {0.3, 0.3, 0.4}, {1, 0, 0})

gr.render(scene, 'chapter03-mesh.png', 256, 160,
          {0, 1.2, 7}, {0, -0.2, -1}, {0, 1, 0}, 40,
          {0.2, 0.2, 0.2}, {key, fill})
