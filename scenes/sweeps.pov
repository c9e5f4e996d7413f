// Sphere sweeps (sphere_sweep): a sphere moved along a spline, its radius following the same
// spline. A red arch of straight pieces whose thickness changes at each point (linear_spline:
// spheres joined by the cones tangent to them, exact), a green snake through a smooth
// uniform B-spline (b_spline, which does not pass through its points), a blue wire bent
// through its points (cubic_spline), and a gold coil (cubic_spline) cut open by a box in a
// difference: the sweep is a solid.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 2.6, -8.5>
  look_at <0, 0.4, -0.5>
  right x * image_width / image_height
  angle 50
}
light_source { <5, 10, -8> color rgb 1 }
light_source { <-6, 4, -5> color rgb 0.3 shadowless }
background { color rgb <0.3, 0.4, 0.6> }

plane { y, -1 pigment { checker color rgb 1 color rgb 0.6 } }

sphere_sweep {
  linear_spline 4, <-3, 0, 0>, 0.3, <-1.5, 1.5, 0>, 0.6, <0, 0, 0>, 0.2, <1, 1, 1>, 0.4
  pigment { color rgb <1, 0.3, 0.2> }
  finish { phong 0.6 }
}
sphere_sweep {
  b_spline 6,
  <-3, -0.5, -1>, 0.2, <-2, 2, -1>, 0.3, <0, -0.5, -1>, 0.1,
  <1.5, 2.5, -1>, 0.3, <2.5, 0, -1>, 0.25, <3, 1, -1>, 0.2
  pigment { color rgb <0.2, 0.8, 0.3> }
}
sphere_sweep {
  cubic_spline 5, <-3, 2, 1>, 0.2, <-2, 2.5, 1>, 0.2, <0, 3, 1>, 0.4, <2, 2, 1>, 0.2, <3, 3, 1>, 0.2
  tolerance 0.01
  pigment { color rgb <0.3, 0.4, 1> }
  translate y * 0.2
}
difference {
  sphere_sweep {
    cubic_spline 8,
    #for (I, 0, 7)
      <cos(I * 1.2) * 0.6, I * 0.18 - 0.9, sin(I * 1.2) * 0.6>, 0.12
    #end
  }
  box { <-1, -1.2, -1>, <0, 1, 0> }
  pigment { color rgb <0.9, 0.7, 0.2> }
  finish { specular 0.5 }
  scale 0.6
  translate <-1.8, -0.45, -2.8>
}
