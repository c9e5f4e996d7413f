// Constructive solid geometry: solids made from boxes, spheres, cylinders, cones, tori and
// planes with union, merge, intersection, difference, inverse and clipped_by. Sheaf keeps
// them as exact CSG trees (no triangles); every object here is one tree.
//
//   back row:  a die, a Steinmetz solid, a glass merge, a bowl
//   front row: a cut cone, a nut, a jack, a sliced ring
//
//   render scenes/csg.pov -W 640 -H 480 -o csg.png
//   povray +Iscenes/csg.pov +W640 +H480 +A +Ocsg.png
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera {
  location <0, 4.2, -9.6>
  look_at <0, 0.45, 0.3>
  right x * image_width / image_height
  angle 45
}

light_source { <-6, 12, -8> color rgb 0.9 }
light_source { <8, 6, -4> color rgb 0.3 }
background { rgb <0.75, 0.8, 0.88> }

plane {
  y, 0
  pigment { checker rgb 0.78 rgb 0.66 scale 1 }
  finish { ambient 0.15 diffuse 0.7 }
}

#declare Plastic = finish { ambient 0.1 diffuse 0.75 phong 0.6 phong_size 60 }

// ---- Back row ----

// A die: the intersection of a cube and a sphere (rounded corners) with dots drilled out of
// it by a difference.
#declare Pip = sphere { 0, 0.13 }
difference {
  intersection {
    box { -0.7, 0.7 }
    sphere { 0, 0.95 }
  }
  object { Pip translate <0, 0.7, 0> }                       // 1 on top
  object { Pip translate <-0.3, 0.3, -0.7> }                 // 2 at the front
  object { Pip translate <0.3, -0.3, -0.7> }
  object { Pip translate <0.7, -0.3, -0.3> }                 // 3 on the right
  object { Pip translate <0.7, 0, 0> }
  object { Pip translate <0.7, 0.3, 0.3> }
  pigment { rgb <0.9, 0.1, 0.1> }
  finish { Plastic }
  rotate y * 25
  translate <-3.3, 0.7, 1.8>
}

// A Steinmetz solid: the intersection of three cylinders along x, y and z.
intersection {
  cylinder { -x, x, 0.75 }
  cylinder { -y, y, 0.75 }
  cylinder { -z, z, 0.75 }
  pigment { rgb <0.95, 0.7, 0.15> }
  finish { Plastic }
  rotate <0, 35, 0>
  translate <-1.1, 0.75, 1.8>
}

// Three glass spheres merged: merge (unlike union) drops the surfaces inside, so no inner
// walls show through the glass.
merge {
  sphere { <-0.35, 0, 0>, 0.55 }
  sphere { <0.35, 0, 0>, 0.55 }
  sphere { <0, 0.55, 0>, 0.5 }
  pigment { rgbf <0.85, 0.95, 1, 0.9> }
  finish { ambient 0 diffuse 0.05 specular 0.8 roughness 0.002 reflection { 0.04, 0.8 fresnel on } conserve_energy }
  interior { ior 1.5 }
  translate <1.1, 0.55, 1.8>
}

// A bowl: a sphere less a smaller one (intersection with an inverse is a difference), cut off
// by a plane.
intersection {
  sphere { 0, 0.9 }
  sphere { 0, 0.8 inverse }
  plane { y, 0.25 }
  pigment { rgb <0.2, 0.45, 0.85> }
  finish { Plastic }
  rotate x * -20 // tipped towards the camera to show its inside
  translate <3.3, 0.85, 1.8>
}

// ---- Front row ----

// A cone cut by a tilted box: the difference shows its solid inside.
difference {
  cone { <0, 0, 0>, 0.85, <0, 1.6, 0>, 0 }
  box { <-1, 0.5, -1>, <1, 2, 0> rotate x * -25 }
  pigment { rgb <0.25, 0.7, 0.3> }
  finish { Plastic }
  rotate y * -30
  translate <-2.6, 0, -1.3>
}

// A hexagonal nut: three boxes at 60 degrees intersected make a hexagonal prism, a cylinder
// drilled through, and the edges chamfered by a double cone.
difference {
  intersection {
    box { <-0.65, -0.3, -1>, <0.65, 0.3, 1> }
    box { <-0.65, -0.3, -1>, <0.65, 0.3, 1> rotate y * 60 }
    box { <-0.65, -0.3, -1>, <0.65, 0.3, 1> rotate y * -60 }
    intersection {
      cone { <0, -0.3, 0>, 0.72, <0, 0.8, 0>, 0 }
      cone { <0, 0.3, 0>, 0.72, <0, -0.8, 0>, 0 }
    }
  }
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.35 }
  pigment { rgb <0.75, 0.76, 0.8> }
  finish { ambient 0.1 diffuse 0.5 specular 0.8 roughness 0.01 metallic reflection 0.25 }
  scale 1.35 translate <-0.87, 0.405, -1.3>
}

// A jack: a union of three rods, each ending in two balls.
#declare Rod = union {
  cylinder { <-0.75, 0, 0>, <0.75, 0, 0>, 0.08 }
  sphere { <-0.75, 0, 0>, 0.15 }
  sphere { <0.75, 0, 0>, 0.15 }
}
union {
  object { Rod }
  object { Rod rotate z * 90 }
  object { Rod rotate y * 90 }
  pigment { rgb <0.6, 0.3, 0.8> }
  finish { Plastic }
  rotate <30, 20, 10>
  translate <0.87, 0.9, -1.3>
}

// A ring lying flat and sliced open by clipped_by: unlike a difference, clipping leaves the
// cut open, so the hollow inside of the torus shows.
torus {
  0.7, 0.25
  clipped_by { plane { z, 0.2 } }
  pigment { rgb <0.95, 0.55, 0.2> }
  finish { Plastic }
  rotate y * 200
  translate <2.6, 0.25, -1.3>
}
