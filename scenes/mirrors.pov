// Mirrors: two mirrors face each other across a checkered floor, so the objects between them
// repeat in a corridor of reflections that grows greener and dimmer with every bounce (the
// mirrors reflect a little more green than red and blue, as real glass mirrors do). A chrome
// ball and a gold ring reflect everything around them; the floor reflects a little too.
//
//   render scenes/mirrors.pov -W 640 -H 480 -o mirrors.png
//   povray +Iscenes/mirrors.pov +W640 +H480 +A +Omirrors.png
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 16 // each further image in the corridor is one more bounce
}

camera {
  location <-2.5, 1.9, -4.2>
  look_at <3, 1.0, 1.4>
  right x * image_width / image_height
  angle 62
}

light_source { <0, 5.5, -2> color rgb 0.9 }
light_source { <-2, 3, -8> color rgb 0.3 shadowless } // a soft fill from behind the camera
background { rgb <0.05, 0.05, 0.08> }

// ---- The room: a checkered floor, a back wall, and two framed mirrors at x = -3 and x = 3 ----
plane {
  y, 0
  pigment { checker rgb <0.85, 0.82, 0.75> rgb <0.12, 0.12, 0.14> scale 0.6 }
  finish { ambient 0.1 diffuse 0.7 reflection 0.08 }
}
box {
  <-3, 0, 4>, <3, 3.5, 4.2>
  pigment { rgb <0.55, 0.35, 0.3> }
  finish { ambient 0.15 diffuse 0.7 }
}

#declare Mirror = texture {
  pigment { rgb 0 }
  finish { ambient 0 diffuse 0 reflection rgb <0.86, 0.92, 0.88> }
}
#declare Frame = texture {
  pigment { rgb <0.45, 0.28, 0.12> }
  finish { ambient 0.1 diffuse 0.7 phong 0.3 }
}

// A mirror of 7 x 2.8 units in the plane x = X, facing the middle of the room, in a frame.
#macro Framed_Mirror(X)
  #local S = (X < 0 ? -1 : 1); // which side of the room it is on
  box { <X, 0.3, -3.5>, <X + 0.02 * S, 3.1, 3.5> texture { Mirror } }
  union {
    box { <X - 0.05 * S, 0.15, -3.65>, <X + 0.1 * S, 0.3, 3.65> }  // bottom
    box { <X - 0.05 * S, 3.1, -3.65>, <X + 0.1 * S, 3.25, 3.65> }  // top
    box { <X - 0.05 * S, 0.15, -3.65>, <X + 0.1 * S, 3.25, -3.5> } // near
    box { <X - 0.05 * S, 0.15, 3.5>, <X + 0.1 * S, 3.25, 3.65> }   // far
    texture { Frame }
  }
#end
Framed_Mirror(-3)
Framed_Mirror(3)

// ---- Between the mirrors ----
// A red ball with a sharp highlight.
sphere {
  <0.4, 0.7, 1.2>, 0.7
  pigment { rgb <0.8, 0.1, 0.08> }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 80 reflection 0.05 }
}
// A chrome ball: nearly all reflection.
sphere {
  <-0.5, 0.55, -1.7>, 0.55
  pigment { rgb <0.9, 0.9, 0.92> }
  finish { ambient 0 diffuse 0.1 specular 0.9 roughness 0.001 reflection 0.85 }
}
// A gold ring standing on its edge: metallic reflection takes the colour of the surface.
torus {
  0.6, 0.12
  rotate x * 90
  rotate y * 30
  translate <1.5, 0.72, -0.5>
  pigment { rgb <0.95, 0.7, 0.3> }
  finish { ambient 0.1 diffuse 0.4 specular 0.6 roughness 0.01 metallic reflection { 0.6 metallic } }
}
// A blue column with a white cap.
cylinder {
  <0.9, 0, 2.8>, <0.9, 2.2, 2.8>, 0.3
  pigment { rgb <0.15, 0.3, 0.8> }
  finish { ambient 0.1 diffuse 0.75 phong 0.5 }
}
sphere { <0.9, 2.4, 2.8>, 0.3 pigment { rgb 0.95 } finish { ambient 0.1 diffuse 0.75 phong 0.5 } }
// A green cone.
cone {
  <-0.8, 0, 2.3>, 0.45, <-0.8, 1.4, 2.3>, 0
  pigment { rgb <0.2, 0.65, 0.3> }
  finish { ambient 0.1 diffuse 0.75 phong 0.3 }
}
