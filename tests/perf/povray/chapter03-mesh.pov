// POV-Ray version of raybook's scenes/chapter03-mesh.lua (three instances of the low-resolution
// Stanford bunny, 3,674 flat triangles, on a box floor; two point lights, hard shadows), for
// `make bench`. The mesh is bunny_L0.inc, POV-Ray's copy of scenes/assets/bunny.obj (the same
// vertices), from the benchmark's POV-Ray folder; give POV-Ray that folder as a library path:
//   povray +Ichapter03-mesh.pov +L<shared>/peers/povray +O/tmp/ch03.png +W256 +H160 -D -GR -A File_Gamma=1.0
//
// Translation from raybook (right-handed, -z into the screen) to POV-Ray (left-handed, +z into
// the screen): every z changes sign, which gives the same picture. The bunny's own vertices are
// mirrored by scale <1,1,-1>; a rotation about y then changes sign (M·Ry(a)·M = Ry(-a) for the
// mirror M, and POV-Ray's rotation matrices are the right-handed ones).
//   camera  A4: eye {0,1.2,7}, view {0,-0.2,-1}, fovy 40 (VERTICAL). POV's angle is horizontal:
//           angle = 2*atan(tan(fovy/2) * W/H), computed below from the image size.
//   finish  POV: pigment kd, diffuse 1, ambient = A4's global ambient (0.2), phong = ks (grey in
//           every material here), phong_size = shininess.
// What differs: POV-Ray computes a highlight even where N·L <= 0; A4 does not.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
background { color rgb 0 }
#include "bunny_L0.inc"
camera { perspective location <0, 1.2, -7> look_at <0, 1.0, -6>
  right x*image_width/image_height
  angle 2*degrees(atan(tan(radians(40/2))*image_width/image_height)) }
light_source { <-4, 6, -6> color rgb <0.9, 0.9, 0.85> }
light_source { < 6, 3, -4> color rgb <0.3, 0.3, 0.4> }

#declare FloorMat = texture { pigment { color rgb <0.55, 0.55, 0.5> }
                              finish { ambient 0.2 diffuse 1 } }
#declare Clay = texture { pigment { color rgb <0.8, 0.55, 0.35> }
                          finish { ambient 0.2 diffuse 1 phong 0.3 phong_size 20 } }
#declare Jade = texture { pigment { color rgb <0.25, 0.6, 0.35> }
                          finish { ambient 0.2 diffuse 1 phong 0.5 phong_size 60 } }

// floor: nh_box corner (-10, -21, -15), size 20
box { <-10, -21, -5>, <10, -1, 15> texture { FloorMat } }
// bunnies: scale 0.2, rotate about y, move to (x, -1, 0); the mesh itself mirrored in z
object { Bunny scale <1, 1, -1> scale 0.2 rotate y*(-30) translate <-2.2, -1, 0> texture { Clay } }
object { Bunny scale <1, 1, -1> scale 0.2 rotate y*0     translate < 0.0, -1, 0> texture { Jade } }
object { Bunny scale <1, 1, -1> scale 0.2 rotate y*30    translate < 2.2, -1, 0> texture { Clay } }
