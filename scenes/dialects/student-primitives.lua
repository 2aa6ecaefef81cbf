-- rt-module: a dialect file (./rt --dialect student-primitives.lua scene.lua), not a scene.
-- student-primitives.lua: primitives and node methods that A5 students often add, built from
-- raybook's A4 primitives so their scenes render before raybook has the real thing:
--   gr.plane(name)              the square y = 0, -1 <= x, z <= 1 (a thin unit cube)
--   gr.cylinder(name)           stands in as a sphere (chapter 15 brings real cylinders)
--   node:set_texture(file)      ignored: the node keeps its material (chapter 10 is planned)
--   node:rotate_xyz(x, y, z)    three rotations, about x, then y, then z, in degrees
-- Transforms here are written in the current order (as applied); in a pre-2015 scene they
-- post-multiply like the scene's own, so a dialect for old scenes lists them in reverse.

function gr.plane(name)
  local plane = gr.node(name)
  local slab = gr.cube(name .. '-slab')
  slab:scale(2, 0.001, 2)
  slab:translate(-1, -0.0005, -1)
  plane:add_child(slab)
  return plane
end

function gr.cylinder(name)
  return gr.sphere(name)
end

function gr.methods.node.set_texture(self, file) end

function gr.methods.node.rotate_xyz(self, x, y, z)
  self:rotate('x', x)
  self:rotate('y', y)
  self:rotate('z', z)
end
