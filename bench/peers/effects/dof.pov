// bench/peers/effects/dof.scene for POV-Ray 3.7: focal blur beside Trazo's thin lens.
// Render: povray +Ibench/peers/effects/dof.pov +W160 +H160 -A +WT1 +FE -D +Odof.exr
// APERTURE (Declare=APERTURE=…) is POV-Ray's `aperture`: Trazo's lens radius 0.25 over k, POV-Ray's lens
// radius per unit of aperture, which coc_calibration.sh measures: k = 0.2497 ± 0.004 (the 3.7 source reads
// r = aperture/2 times a sample grid inside a disk of radius 1/2, k = 1/4), so aperture 1.0.
// BLUR (Declare=BLUR=…) is blur_samples, a fixed budget (variance 0: no adaptive stop).
// Coordinates as Trazo's (right-handed) with `right -x`, as scene1_common.inc does.

#version 3.7;

#ifndef (APERTURE) #declare APERTURE = 1.0; #end
#ifndef (BLUR) #declare BLUR = 256; #end

global_settings {
  assumed_gamma 1.0     // linear, like Trazo's float output
  ambient_light 0
  max_trace_level 1
}

background { rgb 0 }

camera {
  perspective
  location <0, 2, 10>
  look_at <0, 1, 0>
  right -x
  up y
  angle 40              // Trazo's FOV is vertical; square images make it the same
  aperture APERTURE
  blur_samples BLUR, BLUR
  focal_point <0, 1, 0>  // on the axis: the focal plane is at depth |POI − POV| as Trazo's FocalDistance 0
  confidence 0.99
  variance 0
}

// Lambertian, Kd·(N·L)·C with no 1/π: Trazo's Oren–Nayar at Roughness 0.
#declare Lambert = finish { ambient 0 emission 0 diffuse 1 brilliance 1 specular 0 phong 0 }

sphere { <-1.8, 0.7, 4>, 0.7 texture { pigment { rgb <0.9, 0.2, 0.1> } finish { Lambert } } }
sphere { <0, 1, 0>, 1 texture { pigment { rgb <0.9, 0.9, 0.9> } finish { Lambert } } }
sphere { <2.6, 1.2, -5>, 1.2 texture { pigment { rgb <0.1, 0.3, 0.9> } finish { Lambert } } }

// Trazo's Box: the unit cube scaled, then translated. Top face at y = 0.
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> scale <30, 1, 40> translate <0, -0.5, -8>
  texture { pigment { rgb <0.8, 0.8, 0.8> } finish { Lambert } } }

light_source { <5, 8, 6> color rgb <1, 1, 1> fade_power 0 }
