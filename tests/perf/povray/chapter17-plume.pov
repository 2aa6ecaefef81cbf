// POV-Ray version of raybook's tests/perf/ch17/plume.lua: the chapter's VDB smoke plume over a
// grey floor, one point light, in single scattering. For tests/perf/ch17/media_vs_povray.sh
// (make bench, make charts), which first writes the plume's density as a df3 file and its
// placement as an include file with raybook's own reader (tests/perf/ch17/vdb_df3.cpp):
//   build/tests/perf/ch17/ch17_vdb_df3 scenes/assets/plume.nvdb density plume.df3 plume.inc
// then renders like raybook (linear output, no AA, one thread) in the folder of those files:
//   povray +Ichapter17-plume.pov +Oplume.png +W96 +H96 -D -GR -A +WT1 File_Gamma=1.0
// Declare Samples=N for N media samples per interval (default 10), Jitter=J (default 0.5),
// Density=F for another include file than plume.inc.
//
// Translation from raybook (right-handed, -z into the screen) to POV-Ray (left-handed, +z into
// the screen), as in chapter17-media.pov: every z changes sign, which gives the same picture.
//   camera  raybook: eye (0, 1.1, 2.7), view (0, -0.08, -1), up y, fovy 50 (vertical); POV's
//           angle is horizontal: 2*atan(tan(50/2) * W/H).
//   finish  raybook gr.material{kd = 0.2, ks = 0} on the floor cube [-2, 2] x [-0.1, 0] x
//           [-2, 2]: kd * ambient + kd * I (N.L) / 1 (no falloff). POV: pigment 0.2, diffuse 1,
//           ambient 1 with ambient_light set to the scene's ambient (0.05, 0.05, 0.08).
//   light   raybook gr.light({-1.5, 2.6, 1.2}, {4, 4, 3.8}, {1, 0, 0}): no falloff. POV: a
//           point light of that colour, no fade, media_attenuation on (shadow rays are dimmed
//           by the smoke, as raybook's are), media_interaction on.
//   smoke   raybook gr.medium{sigma_s = 30, sigma_a = 3, g = 0.2, density = plume.nvdb} on a
//           group node scaled 1.1 and moved by (0.1, 0, -0.3): the grid's box (its bounds) in
//           that node's space, coefficients per unit of world length. POV: a hollow,
//           transparent box of the same bounds (DensityBox of the df3's unit cube), with the
//           same transform, holding media whose density is the df3 file (interpolate 1:
//           trilinear, on the same samples as raybook's; see vdb_df3.cpp) and
//             scattering { 5 (Henyey-Greenstein), 30 / 4 extinction 4, eccentricity 0.2 },
//             absorption 3, emission 30 * ambient.
//           POV-Ray's phase functions are 4 times raybook's (raybook: pi * HG in A4's light
//           units, HG = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5); POV-Ray's media.cpp:
//           (1 - g^2) / (1 + g^2 - 2 g cos)^1.5, the same cosine: the ray's direction with the
//           direction to the light), so scattering 7.5 scatters as raybook's 30 does, and
//           extinction 4 makes it dim light by 30. raybook's first scattering also returns
//           A4's ambient light (sigma_s * density * ambient per unit length,
//           participating_media.cpp), which POV-Ray's media do not scatter: the emission
//           stands for it. The media's density multiplies all three.
//           Measured at 96x96 (8-bit linear PNGs, red channel; POV-Ray at samples 500, raybook
//           at 256 samples per pixel, --media-bounces=0): the whole image's mean is 0.2170
//           here and 0.2174 in raybook, a crop of the plume (pixels x 30..59, y 5..69) 0.1492
//           and 0.1496, the floor's (rows 75..95) 0.6585 and 0.6565: within 0.5%. With
//           eccentricity -0.2 the plume's crop is 0.2403 here: the cosine's sign is right.
//           media_vs_povray.sh compares each renderer with its own converged picture.
#version 3.7;
#ifndef (Samples) #declare Samples = 10; #end
#ifndef (Jitter) #declare Jitter = 0.5; #end
#ifndef (Density) #declare Density = "plume.inc"; #end
#include Density  // DensityFile, DensityScale, DensityOrigin, DensityBox (ch17_vdb_df3)
global_settings {
  assumed_gamma 1.0
  ambient_light rgb <0.05, 0.05, 0.08>  // gr.render's ambient
}
background { rgb 0 }
camera {
  perspective
  location <0, 1.1, -2.7>
  sky y
  right x * image_width / image_height
  angle 2 * degrees(atan(tan(radians(25)) * image_width / image_height))
  look_at <0, 1.1, -2.7> + <0, -0.08, 1>  // the view direction, z mirrored
}
light_source { <-1.5, 2.6, -1.2> color rgb <4, 4, 3.8> media_attenuation on media_interaction on }

box {  // the floor (raybook z -2..2 is the same span mirrored)
  <-2, -0.1, -2>, <2, 0, 2>
  texture { pigment { rgb 0.2 } finish { ambient 1 diffuse 1 specular 0 phong 0 } }
}

box {  // the smoke: the grid's bounds, in the df3's unit cube, placed as raybook's node
  0, DensityBox
  hollow
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 specular 0 }
  interior {
    media {
      method 3
      intervals 1
      samples Samples
      jitter Jitter
      scattering { 5, rgb 7.5 extinction 4 eccentricity 0.2 }
      absorption rgb 3
      emission rgb 30 * <0.05, 0.05, 0.08>
      density { density_file df3 DensityFile interpolate 1 color_map { [0 rgb 0] [1 rgb 1] } }
    }
  }
  scale DensityScale
  translate DensityOrigin  // the grid's own space
  scale 1.1
  translate <0.1, 0, -0.3>  // raybook's node
  scale <1, 1, -1>          // z mirrored
}
