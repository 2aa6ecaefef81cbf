-- Chapter 16: photon mapping. A Cornell box in the course's style: white floor, ceiling and
-- back wall, a red wall on the left and a green one on the right, one point light under the
-- ceiling. A glass ball (right) focuses the light into a bright caustic inside its shadow,
-- where chapter 5 alone leaves a full, hard shadow; a mirror ball (left) throws a fainter
-- caustic of its own. The indirect map carries light from wall to wall: red and green bleed
-- onto the white floor and ceiling, and it replaces the A4 ambient term.
gr.option('max_depth', 8)
gr.photons{indirect = true}

local white = gr.material{kd = {0.75, 0.75, 0.72}, ks = {0, 0, 0}, shininess = 1}
local red   = gr.material{kd = {0.75, 0.12, 0.10}, ks = {0, 0, 0}, shininess = 1}
local green = gr.material{kd = {0.14, 0.60, 0.15}, ks = {0, 0, 0}, shininess = 1}
local glass = gr.material{kd = {0, 0, 0}, ks = {0.6, 0.6, 0.6}, shininess = 300,
                          ior = 1.5, transparency = 1.0}
local chrome = gr.material{kd = {0.03, 0.03, 0.03}, ks = {0.5, 0.5, 0.5}, shininess = 200,
                           reflect = 0.9}

local root = gr.node('root')

-- The box: five walls, each a unit cube scaled thin, inside x, z in [-1, 1] and y in [0, 2].
local function wall(name, material, sx, sy, sz, x, y, z)
  local w = gr.cube(name)
  w:scale(sx, sy, sz)
  w:translate(x, y, z)
  w:set_material(material)
  root:add_child(w)
end
wall('floor',   white, 2.2, 0.1, 2.2, -1.1, -0.1, -1.1)
wall('ceiling', white, 2.2, 0.1, 2.2, -1.1,  2.0, -1.1)
wall('back',    white, 2.2, 2.2, 0.1, -1.1, -0.1, -1.1)
wall('left',    red,   0.1, 2.2, 2.2, -1.1, -0.1, -1.1)
wall('right',   green, 0.1, 2.2, 2.2,  1.0, -0.1, -1.1)

local ball = gr.sphere('glass ball')
ball:scale(0.4, 0.4, 0.4)
ball:translate(0.42, 0.4, 0.15)
ball:set_material(glass)
root:add_child(ball)

local mirror = gr.sphere('mirror ball')
mirror:scale(0.4, 0.4, 0.4)
mirror:translate(-0.45, 0.4, -0.4)
mirror:set_material(chrome)
root:add_child(mirror)

local light = gr.light({0, 1.8, 0.2}, {0.75, 0.75, 0.72}, {1, 0, 0})
gr.render(root, 'chapter16-photon-mapping.png', 192, 192,
          {0, 1, 3.75}, {0, 0, -1}, {0, 1, 0}, 38,
          {0.12, 0.12, 0.12}, {light})
