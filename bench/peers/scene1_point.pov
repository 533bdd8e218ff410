// Seed scene 1 with its point light (scenes/scene1_point.scene) for POV-Ray 3.7.
// Render: povray +Ibench/peers/scene1_point.pov +W512 +H512 -A +WT2 +FE -D +Oout.exr

#include "scene1_common.inc"

light_source {
  <3, 5, 8>
  color rgb <0.9, 0.9, 0.9>
  fade_power 0  // no distance falloff (SPEC §5); point lights are invisible in Trazo, as here
}
