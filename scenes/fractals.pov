// The fractal patterns: three panels (mandel with a smooth exterior, a julia set with the
// orbit's least distance inside, a fourth-power mandel), a reflective floor of magnet 1 as
// pigment and normal, and a sphere bumped by a julia normal.
//
//   render scenes/fractals.pov -W 640 -H 480 -o fractals.png
//   povray +Iscenes/fractals.pov +W640 +H480 -D +Ofractals.png
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 4 }

camera {
  location <0, 2.2, -6.2>
  look_at <0, 0.9, 0>
  angle 52
  right x * image_width / image_height
}

light_source { <-6, 10, -8>, rgb 1 }
light_source { <6, 4, -6>, rgb 0.4 }
background { rgb <0.05, 0.06, 0.1> }

#declare Panel = box { <-1, -1, 0>, <1, 1, 0.1> }

// Mandel: the escape step wraps through the map; inside, the plain factor.
object {
  Panel
  pigment {
    mandel 60
    exterior 1, 1
    interior 0, 1
    color_map { [0 rgb <0.02, 0.02, 0.1>] [0.15 rgb <0.1, 0.3, 0.9>] [0.4 rgb <1, 1, 1>]
                [0.99 rgb <1, 0.7, 0.2>] [1 rgb 0] }
    scale 0.65 translate <0.35, 0, 0>
  }
  finish { ambient 0.2 diffuse 0.8 }
  rotate <0, -25, 0> translate <-2.2, 1.2, 0.6>
}

// Julia: inside, the orbit's least |z| (interior type 1).
object {
  Panel
  pigment {
    julia <0.353, 0.288>, 40
    interior 1, 1.5
    color_map { [0 rgb <0.3, 0, 0>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 0.9, 0.3>] [1 rgb 1] }
    scale 0.6
  }
  finish { ambient 0.2 diffuse 0.8 }
  translate <0, 1.3, 1.2>
}

// Mandel with exponent 4: |z| on escape (exterior type 6) for smooth bands.
object {
  Panel
  pigment {
    mandel 40
    exponent 4
    exterior 6, 0.2
    interior 1, 1
    color_map { [0 rgb <0, 0.2, 0>] [0.5 rgb <0.3, 1, 0.2>] [1 rgb <1, 1, 0.6>] }
    scale 0.7
  }
  finish { ambient 0.2 diffuse 0.8 }
  rotate <0, 25, 0> translate <2.2, 1.2, 0.6>
}

// A floor of magnet 1: as colour and as bumps, with a mirror sheen.
plane {
  y, 0
  texture {
    pigment {
      magnet 1 mandel 40
      interior 1, 0.8
      color_map { [0 rgb <0.9, 0.75, 0.5>] [1 rgb <0.5, 0.3, 0.25>] }
    }
    normal { magnet 1 mandel 40 0.4 }
    finish { specular 0.4 reflection 0.25 }
    rotate x * 90 translate <-1.5, 0, 0> scale 2.5
  }
}

// A sphere bumped by a julia set.
sphere {
  <0, 0.55, -1.2>, 0.55
  pigment { rgb <0.85, 0.85, 0.9> }
  normal { julia <-0.5, 0.5>, 12 0.6 exponent 3 scale 0.5 }
  finish { specular 0.6 roughness 0.02 reflection 0.15 }
}
