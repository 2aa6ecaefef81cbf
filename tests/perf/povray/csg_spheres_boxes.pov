// The peers' csg.pov ($RB_SHARED/peers/povray/csg.pov) without its cylinders and cones, which
// are chapter 15's: the box minus a sphere and the lens (intersection of two spheres), on the
// same plane under the same two lights and camera. tests/perf/scenes/csg.lua is the same
// scene for raybook (the plane is a thin box there). Used by tests/perf/ch14/csg_vs_povray.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
background { color rgb <0.2, 0.3, 0.5> }
camera { perspective location <0, 3.5, -9> look_at <0, 1, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
light_source { < 6, 6, -3> color rgb <0.5, 0.5, 0.5> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.1 diffuse 0.7 } }
#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 40 }
// box minus sphere
difference {
  box { <-1, 0, -1>, <1, 2, 1> }
  sphere { <0, 1, 0>, 1.3 }
  pigment { color rgb <1.0, 0.2, 0.2> } finish { Fin }
  translate <-2.6, 0, 0> }
// lens: intersection of two spheres
intersection {
  sphere { <-0.6, 1, 0>, 1.2 }
  sphere { < 0.6, 1, 0>, 1.2 }
  pigment { color rgb <0.2, 1.0, 0.2> } finish { Fin }
  translate <0, 0, 1> }
