// POV-Ray version of raybook's scenes/chapter02-phong.lua (A4 Phong: two spheres, three box
// pillars and a cap on a box floor, two point lights, hard shadows), for `make bench`.
// Render like raybook (linear output, no AA), from anywhere:
//   povray +Ichapter02-phong.pov +O/tmp/ch02.png +W256 +H192 -D -GR -A File_Gamma=1.0
//
// Translation from raybook (right-handed, -z into the screen) to POV-Ray (left-handed, +z into
// the screen): every z changes sign, which gives the same picture. A rotation about z keeps its
// angle (POV-Ray's rotation matrices are the right-handed ones, and the mirror commutes with a
// z rotation).
//   camera  A4: eye {0,2,8}, view {0,-0.25,-1}, fovy 50 (VERTICAL). POV's angle is horizontal:
//           angle = 2*atan(tan(fovy/2) * W/H), computed below from the image size.
//   finish  A4: kd*ambient + kd*(N·L)*I + ks*(R·V)^shininess*I. POV: pigment kd, diffuse 1,
//           ambient = A4's global ambient (0.15), phong = ks, phong_size = shininess.
// What differs:
//   * gold's highlight colour ks = {0.8,0.8,0.5}: POV's phong highlight is white (the light's
//     colour), so it uses phong 0.7;
//   * the fill light's falloff {1, 0.02, 0.001} (1/(1 + 0.02 r + 0.001 r²)) has no POV-Ray form
//     (fade_power gives 2/(1 + (r/d)^p)); the light's colour is scaled by the falloff at the
//     scene's centre (r = 10.25 from the origin: factor 0.763) and has no fade;
//   * POV-Ray computes a highlight even where N·L <= 0; A4 does not.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
background { color rgb 0 }
camera { perspective location <0, 2, -8> look_at <0, 1.75, -7>
  right x*image_width/image_height
  angle 2*degrees(atan(tan(radians(50/2))*image_width/image_height)) }
light_source { <-6, 8, -6> color rgb <0.9, 0.9, 0.9> }
light_source { < 5, 4, -8> color rgb <0.5, 0.5, 0.6>*0.7634 }

#declare Red  = texture { pigment { color rgb <0.8, 0.15, 0.1> }
                          finish { ambient 0.15 diffuse 1 phong 0.6 phong_size 40 } }
#declare Blue = texture { pigment { color rgb <0.1, 0.25, 0.8> }
                          finish { ambient 0.15 diffuse 1 phong 0.4 phong_size 15 } }
#declare Grey = texture { pigment { color rgb <0.6, 0.6, 0.55> }
                          finish { ambient 0.15 diffuse 1 } }
#declare Gold = texture { pigment { color rgb <0.75, 0.55, 0.1> }
                          finish { ambient 0.15 diffuse 1 phong 0.7 phong_size 80 } }

// floor: unit cube scaled (20, 0.5, 20) and moved by (-10, -1.5, -10)
box { <-10, -1.5, -10>, <10, -1, 10> texture { Grey } }
// ball: unit sphere scaled 1.2, moved to (-1.6, 0.2, 0)
sphere { <-1.6, 0.2, 0>, 1.2 texture { Red } }
// egg: unit sphere scaled (0.6, 1.3, 0.6), rotated 30° about z, moved to (1.8, 0.3, 0.5)
sphere { 0, 1 scale <0.6, 1.3, 0.6> rotate z*30 translate <1.8, 0.3, -0.5> texture { Blue } }
// three instances of one pillar (nh_box corner (-0.25,-1,-0.25), size 0.5) at x = -2, 0, 2, z = -3
#declare Pillar = box { <-0.25, -1, -0.25>, <0.25, -0.5, 0.25> texture { Gold } }
#for (I, 0, 2)
  object { Pillar translate <-2 + 2*I, 0, 3> }
#end
// cap: nh_sphere at (0, 0.3, -3), radius 0.45
sphere { <0, 0.3, 3>, 0.45 texture { Gold } }
