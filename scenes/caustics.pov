// POV-Ray's fake caustics (interior { caustics c }): light crossing glass is scaled at each
// surface by 1 + |n.d|^(45 c), n the surface's normal, d the light's direction, so glass lit
// head-on throws bright light where its shadow would be. From left to right: a clear ball
// (caustics 1: a bright spot in the middle of its shadow), a tinted ball with caustics 0.3 (a
// wider, softer spot), the same ball without caustics, and a slab with a leopard normal (its
// tilted normals break the light into a network).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 6, -7>
  look_at <0, -0.4, 0.8>
  right x * image_width / image_height
  angle 55
}
light_source { <0.5, 12, 2> color rgb 1 }
light_source { <-6, 5, -6> color rgb 0.25 shadowless }
background { color rgb <0.25, 0.3, 0.4> }

plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.7 scale 0.5 } }

#declare Glass = finish { ambient 0 diffuse 0.1 phong 0.8 phong_size 120 }
sphere { <-3.2, 0.2, 1>, 1
  pigment { color rgbf <1, 1, 1, 0.9> }
  finish { Glass }
  interior { ior 1 caustics 1 }
}
sphere { <-0.9, 0.2, 1>, 1
  pigment { color rgbf <1, 0.7, 0.4, 0.9> }
  finish { Glass }
  interior { ior 1 caustics 0.3 }
}
sphere { <1.4, 0.2, 1>, 1
  pigment { color rgbf <1, 0.7, 0.4, 0.9> }
  finish { Glass }
  interior { ior 1 }
}
box { <2.8, 0.6, 0>, <4.2, 0.8, 2>
  pigment { color rgbf <0.8, 0.9, 1, 0.95> }
  finish { Glass }
  normal { leopard 0.8 scale 0.2 }
  interior { ior 1 caustics 0.5 }
}
