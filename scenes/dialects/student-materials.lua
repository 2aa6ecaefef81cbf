-- rt-module: a dialect file (./rt --dialect student-materials.lua scene.lua), not a scene.
-- student-materials.lua: material calls that A5 students often add, mapped onto raybook's own
-- gr.material{...} table form. A TA passes this file once for the whole class:
--   ./rt --batch class/ --dialect scenes/dialects/student-materials.lua
--
--   gr.mirror_material(kd, ks, shininess, reflectivity)
--   gr.glass_material(kd, ior)                 clear glass: all light transmitted
--   gr.material(kd, ks, shininess, reflectivity, transparency, ior)
--                                              the six-number extension of gr.material,
--                                              replacing raybook's reading of a numeric
--                                              fourth argument (reflectivity only)

local a4material = gr.material

function gr.mirror_material(kd, ks, shininess, reflectivity)
  return gr.material{kd = kd, ks = ks, shininess = shininess, reflect = reflectivity}
end

function gr.glass_material(kd, ior)
  return gr.material{kd = kd, ks = {0.9, 0.9, 0.9}, shininess = 100, ior = ior,
                     transparency = 1}
end

function gr.material(...)
  local kd, ks, shininess, reflectivity, transparency, ior = ...
  if type(reflectivity) ~= 'number' then
    -- The A4 form, a table or seed 000's keywords: raybook's own gr.material reads them.
    return a4material(...)
  end
  local m = {kd = kd, ks = ks, shininess = shininess, reflect = reflectivity}
  if transparency and transparency > 0 then
    m.transparency = transparency
    m.ior = ior or 1.5
  end
  return a4material(m)
end
