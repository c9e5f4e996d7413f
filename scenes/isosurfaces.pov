// Isosurfaces and function patterns: a rock of noise on a sphere, a rounded die, a torus
// twisted by a user function, a pattern made solid, all on a floor coloured by a function.
// The internal functions are declared here as functions.inc declares them.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare f_noise3d = function { internal(76) }
#declare f_sphere = function { internal(61) }
#declare f_rounded_box = function { internal(60) }
#declare f_torus = function { internal(70) }

camera {
  location <0, 4, -8.5>
  look_at <0, 0.8, 0>
  angle 50
  right x * image_width / image_height
}
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -6> rgb 0.35 shadowless }

// The floor: rings of a function, wrapped into [0, 1] as pattern values are.
plane {
  y, 0
  pigment {
    function { sqrt(x * x + z * z) * 0.35 + 0.1 * sin(4 * atan2(x, z)) }
    color_map { [0 rgb <0.75, 0.7, 0.6>] [0.5 rgb <0.45, 0.42, 0.38>] [1 rgb <0.75, 0.7, 0.6>] }
  }
}

// A rock: a sphere pushed in and out by noise.
isosurface {
  function { f_sphere(x, y, z, 0.9) + (f_noise3d(x * 2.5, y * 2.5, z * 2.5) - 0.5) * 0.6 }
  contained_by { sphere { 0, 1.4 } }
  max_gradient 2.5
  pigment { rgb <0.55, 0.5, 0.45> }
  normal { granite 0.2 scale 0.5 }
  translate <-2.7, 1.1, 0.6>
}

// A die: a rounded box with its pips cut as spheres (max over the pips' distances).
#declare Pip = function(x, y, z, a, b) { f_sphere(x - a, y, z - b, 0.17) }
isosurface {
  function {
    max(f_rounded_box(x, y, z, 0.12, 0.7, 0.7, 0.7),
        -min(Pip(x, y - 0.72, z, 0, 0),
             Pip(x, y - 0.72, z, 0.35, 0.35), Pip(x, y - 0.72, z, -0.35, -0.35)))
  }
  contained_by { box { -0.75, 0.75 } }
  pigment { rgb <0.9, 0.12, 0.1> }
  finish { specular 0.5 roughness 0.02 }
  rotate y * 25
  translate <0, 0.7, -0.8>
}

// A torus whose tube swells and thins with the angle around it.
isosurface {
  function { f_torus(x, y, z, 0.9, 0.22 + 0.1 * sin(5 * atan2(x, z))) }
  contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
  max_gradient 1.6
  pigment { rgb <0.2, 0.45, 0.8> }
  finish { specular 0.6 roughness 0.01 reflection 0.1 }
  rotate x * -50
  translate <2.6, 1.1, 0.8>
}

// A pattern made solid: the crackle cells' walls above a threshold, in a sphere.
#declare Walls = function { pattern { crackle scale 0.35 } }
isosurface {
  function { 0.12 - Walls(x, y, z) }
  contained_by { sphere { 0, 0.8 } }
  max_gradient 6
  pigment { rgb <0.85, 0.75, 0.3> }
  translate <0.4, 0.85, 2.4>
}
