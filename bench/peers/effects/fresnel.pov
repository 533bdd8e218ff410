// bench/peers/effects/fresnel.scene for POV-Ray 3.7: Fresnel glass beside Trazo's (SPEC §6 Fresnel).
// Render: povray +Ibench/peers/effects/fresnel.pov +W161 +H161 -A +WT1 +FE -D +Ofresnel.exr
// The glass: `reflection { 0, 1 fresnel on }` (the exact unpolarised F, weighted from 0 to 1) with
// `conserve_energy` (transmission times 1 − F) and `interior { ior 1.5 }`; the pigment is clear, `rgbt 1`
// (TRANSMIT=0: `rgbf 1`, a white filter, the same light). POV-Ray traces both branches at every interface,
// up to max_trace_level, pruning below adc_bailout; Trazo picks one at random inside (both converge to the same).
// -A (no antialiasing) traces the pixel centres, as Trazo's Antialiasing 1. No light sources: every surface
// but the glass is emissive (`emission`, no diffuse), so shadows (Trazo: full; POV-Ray: filtered) do not enter.
// Coordinates as Trazo's (right-handed) with `right -x`, as scene1_common.inc does.

#version 3.7;

#ifndef (TRACE_LEVEL) #declare TRACE_LEVEL = 32; #end
#ifndef (BAILOUT) #declare BAILOUT = 1e-6; #end
#ifndef (TRANSMIT) #declare TRANSMIT = 1; #end

global_settings {
  assumed_gamma 1.0     // linear, like Trazo's float output
  ambient_light 0
  max_trace_level TRACE_LEVEL
  adc_bailout BAILOUT
}

background { rgb 0 }

camera {
  perspective
  location <0, 0, 8.25>
  look_at <0, 0, 0>
  right -x
  up y
  angle 34              // Trazo's FOV is vertical; square images make it the same
}

#macro Emitter(C) texture { pigment { rgb C } finish { ambient 0 diffuse 0 specular 0 emission 1 } } #end

// Trazo's Box: the unit cube scaled, then translated.
#macro TrazoBox(S, T, C)
  box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> scale S translate T Emitter(C) }
#end

sphere { <0, 0, 0>, 1.5
  texture {
    #if (TRANSMIT) pigment { rgbt 1 } #else pigment { rgbf 1 } #end
    finish { ambient 0 diffuse 0 specular 0 phong 0 reflection { 0, 1 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}

TrazoBox(<1000, 1000, 0.2>, <0, 0, -4.1>, <0.25, 0.25, 0.3>)  // the wall
TrazoBox(<1.2, 12, 0.2>, <0, 4, -3.9>, <1, 1, 1>)          // white stripe
TrazoBox(<1.2, 12, 0.2>, <-2.2, 4, -3.9>, <0.9, 0.15, 0.1>) // red stripe
TrazoBox(<1.2, 12, 0.2>, <2.2, 4, -3.9>, <0.1, 0.8, 0.2>)   // green stripe
TrazoBox(<12, 0.8, 0.2>, <0, 1.6, -3.7>, <0.2, 0.3, 1>)     // blue band
TrazoBox(<1000, 0.2, 1000>, <0, -2.1, 0>, <0.6, 0.5, 0.3>)  // the floor
