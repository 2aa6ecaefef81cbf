-- Other courses' primitives, each the nearest shape raybook has: a plane (a large thin box, the
-- blue floor), a triangle and a quad (meshes of their vertices, red and green), a disc (a thin
-- cylinder, yellow-ish white on the floor), a torus (a sphere of its outer radius, magenta-free
-- grey), and a tube (chapter 15's cylinder). Each says what stands in for it.
-- expect-error: primitives.lua:20: gr.plane is not a raybook call
-- expect-stderr: rt: warning: primitives.lua:20: gr.plane: --lenient stands in a thin box 2000 wide, its top the plane y = 0
-- expect-stderr: rt: warning: primitives.lua:24: gr.triangle: --lenient stands in a mesh of its 3 vertices
-- expect-stderr: rt: warning: primitives.lua:28: gr.quad: --lenient stands in a mesh of its 4 vertices
-- expect-stderr: rt: warning: primitives.lua:32: gr.disc: --lenient stands in a cylinder of radius 1, 0.002 thick, in the plane y = 0
-- expect-stderr: rt: warning: primitives.lua:36: gr.torus: --lenient stands in a sphere of its outer radius 1.5
-- expect-stderr: rt: warning: primitives.lua:40: gr.tube: --lenient stands in raybook's gr.cylinder (radius 1, y from -1 to 1)
-- expect-blue: 0 0.9 1 1
-- expect-red: 0.2 0.4 0.35 0.7
-- expect-green: 0.65 0.4 0.8 0.7
-- expect-lit: 0.45 0.2 0.55 0.35
-- expect-lit: 0.45 0.5 0.55 0.65
local function mat(r, g, b) return gr.material({r, g, b}, {0, 0, 0}, 1) end
root = gr.node('root')
-- The floor: a blue plane.
local floor = gr.plane('floor')
floor:set_material(mat(0.1, 0.1, 0.9))
root:add_child(floor)
-- A red triangle, standing on the floor at the left.
local tri = gr.triangle('tri', {-6, 0, 0}, {-3, 0, 0}, {-4.5, 3, 0})
tri:set_material(mat(0.9, 0.1, 0.1))
root:add_child(tri)
-- A green quad (a list of vertices), standing at the right.
local quad = gr.quad('quad', {{3, 0, 0}, {6, 0, 0}, {6, 3, 0}, {3, 3, 0}})
quad:set_material(mat(0.1, 0.9, 0.1))
root:add_child(quad)
-- A white disc lying on the floor in front.
local disc = gr.disc('disc')
disc:translate(0, 0.01, 3)
root:add_child(disc)
-- A torus of major radius 1 and minor radius 0.5 above the centre.
local torus = gr.torus('torus', 1, 0.5)
torus:translate(0, 4.5, 0)
root:add_child(torus)
-- A tube in the middle.
local tube = gr.tube('tube')
tube:translate(0, 1, 0)
root:add_child(tube)
gr.render(root, 'out.png', 80, 60, {0, 4, 16}, {0, -0.25, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 10, 16}, {0.9, 0.9, 0.9}, {1, 0, 0})})
