// Seed scene 1 with its area light (scenes/scene1_area.scene) for POV-Ray 3.7.
// Render: povray +Ibench/peers/scene1_area.pov +W512 +H512 -A +WT2 +FE -D +Oout.exr
// Declare CELLS (e.g. povray ... Declare=CELLS=40) for a denser grid over the same rectangle: the
// converged reference of run_peers.sh.

#include "scene1_common.inc"

#ifndef (CELLS) #declare CELLS = 10; #end  // the scene's Subdivision 10 10

// Trazo's AreaLight: centre (3, 5, 8), normal -z, Width 2 along u = -x, Height 2 along v = +y (SPEC §3),
// split into CELLS x CELLS cells with one uniformly jittered point in each. POV-Ray puts its N points at
// u/(N-1) - 1/2 of an axis and jitters each by +-1/2 of that spacing, so an axis of 2·(N-1)/N makes its
// jitter cells exactly Trazo's cells of the 2 x 2 rectangle.
#declare AxisLength = 2 * (CELLS - 1) / CELLS;

light_source {
  <3, 5, 8>
  color rgb <1, 1, 1>           // POV-Ray splits it over the points: the mean, as Trazo's estimator
  area_light AxisLength * x, AxisLength * y, CELLS, CELLS
  jitter                        // no `adaptive`: POV-Ray's default (level 100) tests every point
  area_illumination on          // N·L per point, not from the centre only
  fade_power 0                  // no distance falloff (SPEC §5)
  // The rectangle is visible in Trazo (it returns the light's colour) and casts no shadow; a looks_like
  // object is placed at the light and never shadows it.
  looks_like {
    polygon { 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
      texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } } }
  }
}
