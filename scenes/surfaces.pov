// Algebraic surfaces and superellipsoids: a torus written as a quartic, an hourglass cut from a
// hyperboloid (quadric), a monkey saddle (cubic) inside a ball, and superellipsoids from a
// rounded box to a pinched star, one drilled by an infinite quadric cylinder. Every one casts
// shadows and is seen in the polished floor: the secondary rays meet the exact surfaces.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }

camera {
  location <0, 5, -7>
  look_at <0, 0.6, 0.5>
  right x * image_width / image_height
  angle 52
}
light_source { <-6, 9, -7> color rgb 1 }
light_source { <5, 6, -3> color rgb 0.35 }
background { color rgb <0.55, 0.65, 0.8> }

plane {
  y, 0
  pigment { checker color rgb 0.85 color rgb 0.45 scale 0.75 }
  finish { diffuse 0.8 reflection 0.2 }
}

#declare Shiny = finish { diffuse 0.75 specular 0.6 roughness 0.01 reflection 0.08 }

// (x^2 + y^2 + z^2 + 1 - r^2)^2 - 4 (x^2 + z^2), r = 0.3: POV-Ray's torus { 1, 0.3 }.
poly {
  4,
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.18,
   0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
   1, 0, 0, 2, 0, 1.82, 0, 0, 0, 0,
   1, 0, -2.18, 0, 0.8281>
  sturm
  pigment { color rgb <1, 0.75, 0.3> }
  finish { Shiny }
  rotate <-60, 0, 20>
  scale 0.8
  translate <-2.6, 1.05, 0.6>
}

// x^2 - y^2 + z^2 = 0.15 between y = -0.8 and 0.8.
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.15 }
  box { <-2, -0.8, -2>, <2, 0.8, 2> }
  pigment { color rgb <0.3, 0.75, 0.45> }
  finish { Shiny }
  translate <-0.9, 0.8, -0.4>
}

// The monkey saddle y = x^3 - 3 x z^2, the solid below it inside a ball.
intersection {
  cubic {
    <1, 0, 0, 0, 0, 0, 0, -3, 0, 0,
     0, 0, 0, 0, 0, -1, 0, 0, 0, 0>
  }
  sphere { 0, 1 }
  pigment { color rgb <0.85, 0.3, 0.35> }
  finish { Shiny }
  rotate y * 25
  scale 0.75
  translate <0.75, 0.8, -0.9>
}

superellipsoid {
  <0.2, 0.2>
  pigment { color rgb <0.35, 0.5, 0.95> }
  finish { Shiny }
  scale 0.55
  rotate <0, 35, 0>
  translate <2.5, 0.55, -0.3>
}

superellipsoid {
  <2.8, 2.8>
  pigment { color rgb <0.95, 0.9, 0.85> }
  finish { Shiny }
  scale 0.75
  rotate <30, 20, 0>
  translate <1.4, 0.9, 1.6>
}

// A rounded drum, drilled along y by the infinite cylinder x^2 + z^2 = 0.16.
difference {
  superellipsoid { <1, 0.3> rotate x * 90 }
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 }
  pigment { color rgb <0.7, 0.45, 0.85> }
  finish { Shiny }
  scale <0.7, 0.35, 0.7>
  translate <0.2, 0.35, 2.6>
}
