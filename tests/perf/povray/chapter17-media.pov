// POV-Ray version of raybook's tests/perf/ch17/shaft.lua: a light shaft through a window into a
// box of homogeneous fog, in single scattering. For tests/perf/ch17/media_vs_povray.sh (make
// bench, make charts). Render like raybook (linear output, no AA, one thread), from anywhere:
//   povray +Ichapter17-media.pov +O/tmp/ch17.png +W160 +H120 -D -GR -A +WT1 File_Gamma=1.0
// Declare Samples=N (povray ... Declare=Samples=N) for N media samples per interval (default 10),
// Jitter=J for jitter (default 0.5).
//
// Translation from raybook (right-handed, -z into the screen) to POV-Ray (left-handed, +z into
// the screen): every z changes sign, which gives the same picture; a raybook box spanning
// [z0, z1] spans [-z1, -z0] here.
//   camera  raybook: eye (0.2, 1.1, 3.4), view (-0.1, -0.15, -1), up y, fovy 55 (VERTICAL).
//           POV's angle is horizontal: 2*atan(tan(55/2) * W/H), computed from the image size.
//   finish  raybook gr.material{kd = 0.5, ks = 0}: kd*(N·L)*I, no ambient (the scene's ambient
//           is 0). POV: pigment 0.5, diffuse 1, ambient 0.
//   light   raybook gr.light({-3, 3, -0.1}, 8, {1, 0, 0}): no falloff. POV: a point light of
//           colour 8 (no fade), media_attenuation on (shadow rays are dimmed by the fog, as
//           raybook's are; POV's default is off), media_interaction on.
//   fog     raybook gr.medium{sigma_s = 0.3, sigma_a = 0.03, g = 0} filling a material-less
//           cube [-1, 1.5] x [-0.05, 2] x [-1.5, 1.5] (its bottom below the floor's top: with
//           coplanar faces POV-Ray lost most of the light on the floor): a hollow, fully
//           transparent box whose interior holds scattering { 1 (isotropic), 0.075 extinction 4 }
//           and absorption 0.03. POV-Ray's isotropic phase function is 4 times raybook's (which
//           is pi/(4 pi) in A4's light units): scattering 0.075 scatters as much light as
//           raybook's 0.3, and extinction 4 makes it dim light by 0.3 as raybook's does.
//           Measured: converged, the shaft's mean (an 8-bit crop) is 0.199 here and 0.193 in
//           raybook, the whole image's 0.0287 and 0.0285. Method 3 (POV-Ray's default:
//           adaptive, one interval) with Samples samples; the shaft is single scattering in
//           both renderers (raybook with --media-bounces=0). media_vs_povray.sh compares each
//           renderer with its own converged picture.
#version 3.7;
#ifndef (Samples) #declare Samples = 10; #end
#ifndef (Jitter) #declare Jitter = 0.5; #end
global_settings {
  assumed_gamma 1.0
  max_trace_level 2  // the scene's gr.option('max_depth', 2)
  ambient_light 0
}
background { rgb 0 }
camera {
  perspective
  location <0.2, 1.1, -3.4>
  sky y
  right x * image_width / image_height
  angle 2 * degrees(atan(tan(radians(27.5)) * image_width / image_height))
  look_at <0.2, 1.1, -3.4> + <-0.1, -0.15, 1>  // the view direction, z mirrored
}
light_source { <-3, 3, 0.1> color rgb 8 media_attenuation on media_interaction on }

#declare Grey = texture { pigment { rgb 0.5 } finish { ambient 0 diffuse 1 specular 0 phong 0 } }
box { <-1, -0.1, -2>, <2, 0, 2> texture { Grey } }             // floor
box { <-1.1, 0, -2>, <-1, 1.0, 2> texture { Grey } }           // wall below the window
box { <-1.1, 1.6, -2>, <-1, 4, 2> texture { Grey } }           // wall above
box { <-1.1, 1.0, 0.4>, <-1, 1.6, 2> texture { Grey } }        // wall behind (raybook z -2..-0.4)
box { <-1.1, 1.0, -2>, <-1, 1.6, -0.2> texture { Grey } }      // wall in front (raybook z 0.2..2)

box {  // the fog
  <-1, -0.05, -1.5>, <1.5, 2, 1.5>
  hollow
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 specular 0 }
  interior {
    media {
      method 3
      intervals 1
      samples Samples
      jitter Jitter
      scattering { 1, rgb 0.075 extinction 4 }
      absorption rgb 0.03
    }
  }
}
