-- rt-module: a dialect file (./rt --dialect student-lights.lua scene.lua), not a scene.
-- student-lights.lua: light calls that A5 students often add, mapped onto raybook's lights:
--   gr.area_light_rect(position, colour, falloff, width, height)
--                              a rectangle facing down (-y), sampled 4 x 4
--   gr.sphere_light(position, colour, falloff, radius)
--                              seed 002's ball light

function gr.area_light_rect(position, colour, falloff, width, height)
  return gr.area_light{position = position, colour = colour, falloff = falloff,
                       size = {width, height}, normal = {0, -1, 0}, left = {1, 0, 0},
                       samples = 4}
end

function gr.sphere_light(position, colour, falloff, radius)
  return gr.ball_light(position, colour, falloff, radius)
end
