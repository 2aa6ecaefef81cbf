-- Chapter 9: smooth meshes. Five meshes in a row under a light from the upper left, so that
-- each one's terminator (where lit turns to unlit) runs down its middle:
--   1. the 80-triangle icosphere as chapter 3 draws it (gr.mesh): flat facets;
--   2. the same file with its `vn` interpolated, shadow rays from the flat facets
--      (terminator = false): the terminator breaks into the triangles' steps;
--   3. the same with the terminator fix (the default): shadow rays start on the curved
--      surface the normals describe, and the terminator is smooth;
--   4. the Stanford bunny (3,674 triangles, no `vn`) with angle-weighted computed normals;
--   5. a cube from an OBJ file without `vn`: its 90-degree edges are sharper than the default
--      60-degree crease, so it stays a cube.
-- Below them, a mirror floor reflects their undersides. Compare with
-- --features=all,-smooth_mesh (everything faceted) and --terminator=none.
local clay  = gr.material({0.8, 0.45, 0.3}, {0.4, 0.4, 0.4}, 40)
local bunnyM = gr.material({0.85, 0.8, 0.7}, {0.3, 0.3, 0.3}, 25)
local cubeM = gr.material({0.3, 0.5, 0.8}, {0.3, 0.3, 0.3}, 25)
local floorM = gr.material{kd = {0.25, 0.25, 0.28}, ks = {0.2, 0.2, 0.2}, shininess = 20,
                           reflect = 0.35}

local root = gr.node('root')

local flat = gr.mesh('flat', 'assets/icosphere80.obj')
flat:translate(-4.4, 0, 0)
flat:set_material(clay)
root:add_child(flat)

local stepped = gr.smooth_mesh('stepped', 'assets/icosphere80.obj', {terminator = false})
stepped:translate(-2.2, 0, 0)
stepped:set_material(clay)
root:add_child(stepped)

local smooth = gr.smooth_mesh('smooth', 'assets/icosphere80.obj')
smooth:set_material(clay)
root:add_child(smooth)

local bunny = gr.smooth_mesh('bunny', 'assets/bunny.obj', {normals = 'computed'})
bunny:scale(0.32, 0.32, 0.32)
bunny:translate(2.0, -1.05, -0.3)
bunny:set_material(bunnyM)
root:add_child(bunny)

local cube = gr.smooth_mesh('cube', 'assets/cube.obj')
cube:translate(-0.5, -0.5, -0.5)
cube:scale(1.3, 1.3, 1.3)
cube:rotate('y', 35)
cube:rotate('x', 20)
cube:translate(4.5, -0.2, 0)
cube:set_material(cubeM)
root:add_child(cube)

local floor = gr.cube('floor')
floor:translate(-0.5, -1, -0.5)
floor:scale(14, 0.2, 6)
floor:translate(0, -1.1, 0)
floor:set_material(floorM)
root:add_child(floor)

gr.render(root, 'chapter09-smooth-meshes.png', 256, 96, {0, 1.2, 11}, {0, -1.2, -11}, {0, 1, 0},
          28, {0.15, 0.15, 0.15}, {gr.light({-30, 10, 4}, {0.9, 0.9, 0.9}, {1, 0, 0})})
