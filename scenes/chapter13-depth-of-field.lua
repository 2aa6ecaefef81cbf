-- Chapter 13: depth of field. Five balls stand in a diagonal row on a checkerboard, from just in
-- front of the camera to far behind. The camera's view points at the middle (green) ball, and
-- a thin lens with a disk aperture 0.35 units wide focuses there by default (the focus
-- distance is |view|, seed 000's distance to the target): the green ball and the squares beside
-- it are sharp, the near red ball and the far balls blur, each by the thin-lens circle
-- aperture * |1/focus - 1/depth|. 16 lens samples per pixel are paired with the 16 jittered
-- pixel samples (16 rays, not 256). Compare: --dof-aperture 0 (a pinhole), --dof-focus 4 (the
-- red ball in focus), --dof-shape square (seed 001's aperture), --dof-samples 64 --spp 64.
gr.antialias{sampler = 'jittered', samples = 16}
gr.lens{aperture = 0.35, samples = 16, shape = 'disk'}

local white = gr.material({0.85, 0.85, 0.8}, {0.1, 0.1, 0.1}, 10)
local black = gr.material({0.08, 0.08, 0.1}, {0.1, 0.1, 0.1}, 10)
local colours = {{0.85, 0.15, 0.1}, {0.9, 0.6, 0.1}, {0.15, 0.7, 0.2}, {0.15, 0.35, 0.85},
                 {0.6, 0.2, 0.75}}

local scene = gr.node('root')

-- The checkerboard: unit tiles from z = 5 back to z = -24.
for i = -8, 7 do
  for k = -24, 4 do
    local tile = gr.cube('tile')
    tile:scale(1, 0.2, 1)
    tile:translate(i, -0.2, k)
    tile:set_material((i + k) % 2 == 0 and white or black)
    scene:add_child(tile)
  end
end

-- The balls, radius 0.5, at distances about 4, 6, 8 (the focus), 12 and 18 from the eye.
local places = {{-1.2, 2.2}, {-0.1, 0.2}, {0.6, -1.8}, {1.6, -5.8}, {2.8, -11.8}}
for n, p in ipairs(places) do
  local ball = gr.nh_sphere('ball' .. n, {p[1], 0.5, p[2]}, 0.5)
  ball:set_material(gr.material(colours[n], {0.5, 0.5, 0.5}, 40))
  scene:add_child(ball)
end

local sun = gr.light({-6, 9, 8}, {0.85, 0.85, 0.8}, {1, 0, 0})
local fill = gr.light({6, 4, 5}, {0.3, 0.3, 0.35}, {1, 0, 0})

-- view = target - eye: the green ball's centre, 8 units away.
local eye = {0, 1.5, 6}
local target = {0.6, 0.5, -1.8}
gr.render(scene, 'chapter13-depth-of-field.png', 192, 128,
          eye, {target[1] - eye[1], target[2] - eye[2], target[3] - eye[3]}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {sun, fill})
