// POV-Ray version of raybook's scenes/chapter16-photon-mapping.lua with caustics only (the
// raybook side runs the scene with gr.photons{indirect = false}; POV-Ray has no indirect map,
// and radiosity is left out): a Cornell box, a glass ball and a mirror ball, one point light;
// the light focused by the balls onto the walls is POV-Ray's photon map. For
// tests/perf/ch16/caustics_vs_povray.sh (make bench, make charts). Render like raybook (linear
// output, no AA), from anywhere:
//   povray +Ichapter16-caustics.pov +O/tmp/ch16.png +W192 +H192 -D -GR -A File_Gamma=1.0
// Declare Photons=0 (povray ... Declare=Photons=0) for no photons, or Photons=N for about N
// photons (the count keyword; default 20000). Declare InverseSquare=K for a physical point light
// (1/d² falloff) as bright at distance sqrt(K) as the chapter's; caustics_vs_povray.sh uses
// K = 2.25 with the same light in raybook (gr.light(..., 2.25 x colour, {0, 0, 1})), because the
// chapter's light has no falloff and POV-Ray keeps that along a photon's whole path where
// raybook applies it only up to the first surface (the script says how this was measured).
//
// Translation from raybook (right-handed, -z into the screen) to POV-Ray (left-handed, +z into
// the screen): every z changes sign, which gives the same picture.
//   walls   A4's gr.cube is the unit cube [0, 1]^3; each wall is scaled, then translated, in the
//           order written, so it spans [t, t + s] on each axis; with z mirrored the z range
//           [tz, tz + sz] becomes [-(tz + sz), -tz].
//   camera  A4: eye {0, 1, 3.75}, view {0, 0, -1}, up y, fovy 38 (VERTICAL). POV's angle is
//           horizontal: angle = 2*atan(tan(fovy/2) * W/H), computed below from the image size.
//   finish  A4: kd*ambient + kd*(N·L)*I + ks*(R·V)^shininess*I. POV: pigment kd, diffuse 1,
//           ambient = A4's global ambient (0.12), phong = ks, phong_size = shininess.
//   mirror  chrome: kd 0.03, ks 0.5, shininess 200, reflect 0.9 -> reflection 0.9 added to the
//           Phong colour (raybook's chapter 4 adds reflect x the mirrored ray).
//   glass   kd 0, ks 0.6, shininess 300, ior 1.5, transparency 1: raybook shades only the
//           Fresnel split (exact Fresnel) of a fully transparent surface, no highlight; POV-Ray:
//           filter 1 pigment, reflection 0..1 with Fresnel, ior 1.5, no phong.
// Photons: the light shoots photons for reflection and refraction; the glass ball is a target
// that reflects and refracts them, the mirror ball a target that reflects them; neither collects
// photons (raybook stores none on glass; its chrome has kd 0.03, whose caustic is invisible).
// POV-Ray's gather is its own (20 to 100 photons, adaptive radius); see
// tests/perf/ch16/caustics_vs_povray.sh for what differs from raybook's.
#version 3.7;
#ifndef (Photons) #declare Photons = 20000; #end
global_settings {
  assumed_gamma 1.0
  max_trace_level 8  // the scene's gr.option('max_depth', 8)
  #if (Photons > 0)
    photons { count Photons autostop 0 }
  #end
}
background { color rgb 0 }
camera { perspective location <0, 1, -3.75> look_at <0, 1, 0>
  right x*image_width/image_height
  angle 2*degrees(atan(tan(radians(38/2))*image_width/image_height)) }
#ifndef (InverseSquare) #declare InverseSquare = 0; #end
#if (InverseSquare)
  // A physical point light: 2/(1 + (d/0.01)^2) is 2·0.01²/d² within 0.25% beyond d = 0.2.
  light_source { <0, 1.8, -0.2> color rgb <0.75, 0.75, 0.72>*InverseSquare/(2*0.01*0.01)
    fade_distance 0.01 fade_power 2 photons { reflection on refraction on } }
#else
  light_source { <0, 1.8, -0.2> color rgb <0.75, 0.75, 0.72> photons { reflection on refraction on } }
#end

#declare Wall = finish { ambient 0.12 diffuse 1 }
// floor: scale (2.2, 0.1, 2.2), translate (-1.1, -0.1, -1.1)
box { <-1.1, -0.1, -1.1>, <1.1, 0.0, 1.1> pigment { color rgb <0.75, 0.75, 0.72> } finish { Wall } }
// ceiling: scale (2.2, 0.1, 2.2), translate (-1.1, 2.0, -1.1)
box { <-1.1, 2.0, -1.1>, <1.1, 2.1, 1.1> pigment { color rgb <0.75, 0.75, 0.72> } finish { Wall } }
// back: scale (2.2, 2.2, 0.1), translate (-1.1, -0.1, -1.1): z in [-1.1, -1.0] -> [1.0, 1.1]
box { <-1.1, -0.1, 1.0>, <1.1, 2.1, 1.1> pigment { color rgb <0.75, 0.75, 0.72> } finish { Wall } }
// left (red): scale (0.1, 2.2, 2.2), translate (-1.1, -0.1, -1.1)
box { <-1.1, -0.1, -1.1>, <-1.0, 2.1, 1.1> pigment { color rgb <0.75, 0.12, 0.10> } finish { Wall } }
// right (green): scale (0.1, 2.2, 2.2), translate (1.0, -0.1, -1.1)
box { <1.0, -0.1, -1.1>, <1.1, 2.1, 1.1> pigment { color rgb <0.14, 0.60, 0.15> } finish { Wall } }

// glass ball: unit sphere scaled 0.4, moved to (0.42, 0.4, 0.15)
sphere { <0.42, 0.4, -0.15>, 0.4
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0.0, 1.0 fresnel on } conserve_energy }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off } }
// mirror ball: unit sphere scaled 0.4, moved to (-0.45, 0.4, -0.4)
sphere { <-0.45, 0.4, 0.4>, 0.4
  pigment { color rgb <0.03, 0.03, 0.03> }
  finish { ambient 0.12 diffuse 1 phong 0.5 phong_size 200 reflection { 0.9 } }
  photons { target reflection on collect off } }
