// Functions of pigments and patterns: a floor coloured by a function of a pigment whose map
// holds other pigments, a wall of bands that a pattern function repeats with a warp and reads
// through a pigment_pattern, a terrace raised from a pigment as a height field, a helix and a
// superellipsoid from POV-Ray's internal functions. Nothing here depends on noise, so povray
// draws the same picture.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "functions.inc"

camera {
  location <0, 3.2, -7.5>
  look_at <0, 1.0, 0>
  angle 52
  right x * image_width / image_height
}
light_source { <-5, 9, -7> rgb 1 }
light_source { <6, 4, -5> rgb 0.3 shadowless }

// A pigment whose map holds pigments: a checker of two gradients, and its function's gray.
#declare Tiles = function {
  pigment {
    checker
      pigment { gradient x color_map { [0 rgb 0.2] [1 rgb 0.9] } }
      pigment { gradient z color_map { [0 rgb 0.9] [1 rgb 0.3] } }
  }
}
plane {
  y, 0
  pigment {
    function { Tiles(x, y, z).gray }
    color_map { [0 rgb <0.35, 0.3, 0.25>] [1 rgb <0.9, 0.85, 0.75>] }
  }
}

// Bands: a pattern function of a pigment_pattern, repeated every 0.75 by a warp.
#declare Bands = function {
  pattern {
    pigment_pattern { gradient x color_map { [0 rgb 0] [0.5 rgb 1] [1 rgb 0] } }
    warp { repeat x * 0.75 }
  }
}
box {
  <-4, 0, 3>, <4, 3.5, 3.2>
  pigment {
    function { Bands(x, y, z) * 0.7 + 0.3 * Bands(y, x, z) }
    color_map { [0 rgb <0.2, 0.3, 0.55>] [1 rgb <0.85, 0.9, 1>] }
  }
}

// A terrace: a height field of a pigment function, two sloping steps from a pigment map
// of gradients.
#declare Low = pigment { gradient z color_map { [0 rgb 0.05] [1 rgb 0.3] } }
#declare High = pigment { gradient z color_map { [0 rgb 0.45] [1 rgb 0.8] } }
height_field {
  function 64, 64 {
    pigment { gradient x pigment_map { [0 Low] [0.5 Low] [0.5 High] [1 High] } }
  }
  pigment { rgb <0.55, 0.7, 0.4> }
  scale <2, 1.2, 2>
  translate <1.2, 0, -1.8>
}

// A helix (f_helix1) and a superellipsoid (f_superellipsoid).
isosurface {
  function { f_helix1(x, y, z, 2, 2.5, 0.18, 0.55, 1, 1, 0) }
  contained_by { box { <-0.9, -1.1, -0.9>, <0.9, 1.1, 0.9> } }
  max_gradient 4
  pigment { rgb <0.85, 0.55, 0.2> }
  finish { specular 0.4 roughness 0.02 }
  translate <-2.2, 1.1, 0.2>
}
isosurface {
  function { -f_superellipsoid(x, y, z, 0.25, 0.5) }
  contained_by { box { -1.1, 1.1 } }
  max_gradient 6
  pigment { rgb <0.7, 0.2, 0.25> }
  finish { specular 0.5 roughness 0.01 }
  scale 0.7
  translate <-0.3, 0.7, 0.6>
}
