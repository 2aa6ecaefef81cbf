-- Benchmark scene "empty": raybook's version of POV-Ray's empty.pov benchmark scene: a camera and
-- nothing else, 512x512. It measures the fixed cost of a render: every camera ray misses.
-- POV-Ray's camera: location <0,2.5,-8> look_at <0,1,0> angle 50 (horizontal, = fovy 50° for a
-- square image), mirrored in z for raybook's right-handed space. The background is black
-- (POV's is rgb <0.2,0.3,0.5>; A4 has no background colour). A4 needs one light, which lights
-- nothing here.
local scene = gr.node('root')
local light = gr.light({-5, 8, 6}, {0.8, 0.8, 0.8}, {1, 0, 0})
gr.render(scene, 'empty.png', 512, 512,
          {0, 2.5, 8}, {0, -1.5, -8}, {0, 1, 0}, 50,
          {0.1, 0.1, 0.1}, {light})
