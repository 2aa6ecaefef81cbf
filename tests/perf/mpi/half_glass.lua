-- The uneven scene of the MPI balance benchmark (tests/perf/mpi/mpi_bench.sh): the top half of
-- the picture is a wall of glass balls (each pixel refracts up to 8 times), the bottom half a
-- plain diffuse floor. A static split into bands of rows gives the first ranks all the glass.
gr.option('max_depth', 8)

local floor = gr.material{kd = {0.6, 0.55, 0.5}, ks = {0, 0, 0}, shininess = 1}
local back  = gr.material{kd = {0.3, 0.4, 0.6}, ks = {0, 0, 0}, shininess = 1}
local glass = gr.material{kd = {0.05, 0.05, 0.05}, ks = {0.5, 0.5, 0.5}, shininess = 200,
                          ior = 1.5, transparency = 0.95}

local scene = gr.node('root')
local ground = gr.nh_box('floor', {-20, -41, -30}, 40)
ground:set_material(floor)
scene:add_child(ground)
local wall = gr.nh_box('back', {-20, -20, -52}, 40)
wall:set_material(back)
scene:add_child(wall)

-- Glass balls filling the top half of the view, two layers deep.
for i = -6, 6 do
  for j = 0, 4 do
    for k = 0, 1 do
      local ball = gr.nh_sphere('ball', {i * 0.9 + k * 0.45, 0.45 + j * 0.9, -3 - k * 0.9}, 0.5)
      ball:set_material(glass)
      scene:add_child(ball)
    end
  end
end

gr.render(scene, 'half_glass.png', 256, 256, {0, 0, 8}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {gr.light({3, 8, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})})
