// raybook's tests/perf/scenes/mirror_glass.lua in POV-Ray: the peers' mirror_glass.pov
// (../../../../shared/peers/povray/mirror_glass.pov) with its checker plane replaced by the plain
// grey the Lua scene has (procedural textures come in chapter 10) and its blue background by
// raybook's black, so that antialiasing has the
// same edges to find in both renderers. Everything else is mirror_glass.inc as it is.
// Used by tests/perf/ch08/aa_vs_povray.sh (make bench, make charts).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { perspective location <0, 2.5, -8> look_at <0, 1, 0> right x*image_width/image_height angle 50 }
background { color rgb <0, 0, 0> }  // raybook has no background colour: black
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
light_source { < 6, 6, -3> color rgb <0.5, 0.5, 0.5> }
plane { y, 0
  pigment { color rgb <0.5, 0.5, 0.5> }
  finish { ambient 0.1 diffuse 0.7 } }
sphere { <-1.3, 1, 0.5>, 1
  pigment { color rgb <0, 0, 0> }
  finish { ambient 0 diffuse 0 phong 0.8 phong_size 80 reflection { 0.9 } } }
sphere { <1.3, 1, -0.5>, 1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 phong 0.8 phong_size 80 reflection { 0.0, 1.0 fresnel on } conserve_energy }
  interior { ior 1.5 } }
sphere { <0, 0.6, 3>, 0.6 pigment { color rgb <1.0, 0.6, 0.1> } finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 } }
