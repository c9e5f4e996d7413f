// POV-Ray's mesh camera and uv mapping. The camera is a mesh of one tiny face per pixel, all at
// the eye, each turned to look where a perspective camera's pixel looks (a pinhole camera made
// of faces: mesh_camera distribution 0 takes face i for pixel i, the ray along its normal).
// Before it: a mirrored ball, a checkered floor, and a mesh2 panel whose uv coordinates map
// a checker and a gradient (uv_mapping) across it whatever its place and size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Eye = <0, 1.6, -6>;
#declare Focal = 1.2; // the screen's distance for a height of 1
#declare Faces = mesh {
  #declare J = 0;
  #while (J < image_height)
    #declare I = 0;
    #while (I < image_width)
      #declare D = vnormalize(<((I + 0.5) / image_width - 0.5) * image_width / image_height,
                               0.5 - (J + 0.5) / image_height, Focal>);
      #declare T1 = vnormalize(vcross(y, D));
      #declare T2 = vcross(D, T1);
      // POV-Ray's face normal is cross(P3 - P1, P2 - P1): here cross(T1, T2) = D.
      triangle { <0, 0, 0>, T2 * 1e-4, T1 * 1e-4 }
      #declare I = I + 1;
    #end
    #declare J = J + 1;
  #end
}

camera {
  mesh_camera { 1 0 mesh { Faces rotate x * 8 translate Eye } }
  location <0, 0, 0>
}

light_source { <4, 8, -5> color rgb 1 }
light_source { <-6, 4, -3> color rgb 0.3 shadowless }
background { color rgb <0.3, 0.35, 0.45> }

plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.35 } }

sphere { <-1.3, 1, 0.5>, 1
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { phong 0.6 reflection 0.25 }
}

// A panel 2 x 2 units whose uv square is (0, 0) to (1, 1): the checker has 4 x 4 cells and the
// gradient runs once across it, at any scale.
#declare Panel = mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
}
object { Panel
  texture {
    uv_mapping
    pigment { checker color rgb <0.1, 0.4, 0.9> color rgb 1 scale 0.25 }
    finish { ambient 0.3 }
  }
  scale 2 rotate y * -25 translate <0.6, 0.1, 1.2>
}
object { Panel
  texture {
    pigment { uv_mapping gradient x color_map { [0 color rgb <1, 0.8, 0>] [1 color rgb <0, 0.6, 0.2>] } }
    finish { ambient 0.3 }
  }
  scale <1.2, 0.8, 1> rotate y * 20 translate <-2.8, 2.3, 2>
}
