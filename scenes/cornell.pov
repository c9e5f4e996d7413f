// The built-in scene "cornell" (core/scenes/builtin_cornell.cpp) in POV-Ray's language: one
// reflective object (a sphere ringed by a tilted torus, 778 triangles) inside a closed box of
// six tinted mirrors, 790 triangles in 7 mesh objects, traced with two bounces.
//
//   render scenes/cornell.pov -W 640 -H 480 -o cornell.png     (the same picture as builtin:cornell)
//   povray +Iscenes/cornell.pov +W640 +H480 -D +Ocornell.png
//
// Coordinates are the C++ scene's with z negated (POV-Ray is left-handed; see shapes.inc).
#version 3.7;
#include "shapes.inc"

global_settings {
  assumed_gamma 1.0
  max_trace_level 3 // the primary ray and two reflection bounces (Sheaf: trace.depth=2)
}

// The box spans [-Half, Half] on every axis.
#declare Half = 3;

// A 55 degree vertical field of view, whatever the picture's shape.
camera {
  perspective
  location <0.6, 0.7, -2.6>
  up y
  right x * image_width / image_height
  direction z * 0.5 / tan(radians(55 / 2))
  look_at <0, 0, 0>
}

light_source { <-1.6, 2.3, -1.8> color rgb 1 }
background { rgb 0 }

// The walls: tinted, mostly mirror.
#macro Mirror(Tint)
  texture {
    pigment { rgb Tint }
    finish { ambient 0.1 diffuse 0.2 phong 0.3 phong_size 40 reflection 0.85 }
  }
#end

#declare Gold = texture {
  pigment { rgb <0.95, 0.75, 0.35> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 60 reflection 0.4 }
}

// One wall: a parallelogram from Corner spanned by EU and EV (two triangles), facing into
// the box, as its own mesh object.
#macro Wall(Corner, EU, EV, Tint)
  #local Tex = Mirror(Tint)
  Sh_Reset()
  Sh_Quad(Corner, EU, EV, 1, 1)
  Sh_Object(Tex)
#end

#declare S = 2 * Half;
Sh_Begin(600, 800)
Wall(<-Half, -Half, Half>, <0, 0, -S>, <S, 0, 0>, <0.85, 0.85, 0.85>) // floor
Wall(<-Half, Half, Half>, <S, 0, 0>, <0, 0, -S>, <0.85, 0.85, 0.85>)  // ceiling
Wall(<-Half, -Half, Half>, <0, S, 0>, <0, 0, -S>, <0.9, 0.35, 0.3>)   // left
Wall(<Half, -Half, Half>, <0, 0, -S>, <0, S, 0>, <0.3, 0.85, 0.35>)   // right
Wall(<-Half, -Half, Half>, <S, 0, 0>, <0, S, 0>, <0.4, 0.5, 0.95>)    // back (behind the object)
Wall(<-Half, -Half, -Half>, <0, S, 0>, <S, 0, 0>, <0.95, 0.85, 0.4>)  // front (behind the camera)

// The central object: a sphere (440 triangles) with a tilted ring (338), one mesh.
Sh_Reset()
Sh_Sphere(<0, 0, 0>, 0.75, 11, 22)
Sh_Torus(<0, 0, 0>, <0.35, 1, -0.2>, 1.2, 0.17, 13, 13)
Sh_Object(Gold)
