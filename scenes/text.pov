// Text and prisms: TrueType glyphs and spline outlines extruded into solids (POV-Ray's text
// and prism objects) and used like any other shape. A stone plaque with a word engraved in it
// (difference), a word in red glass standing before it, gold letters stepping up a stair of
// offsets, and a rounded blue frame (a quadratic_spline prism whose inner contour is a hole).
// The fonts are POV-Ray's own (Debian's povray-includes); the shadows and the polished floor
// show that secondary rays meet the exact outlines too.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera {
  location <0.2, 2.6, -6.5>
  look_at <0.2, 1.1, 0>
  right x * image_width / image_height
  angle 50
}
light_source { <-5, 8, -9> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.3 }
background { color rgb <0.5, 0.6, 0.75> }

plane {
  y, 0
  pigment { checker color rgb 0.8 color rgb 0.5 scale 0.8 }
  finish { diffuse 0.8 reflection 0.15 }
}

// The plaque: "SHEAF" cut 0.15 deep into its face.
difference {
  box { <-2.4, 0.3, 0>, <2.4, 2.1, 0.4> }
  text {
    ttf "timrom.ttf" "SHEAF" 1, 0
    scale <1.2, 1.2, 0.3>
    translate <-1.9, 0.75, -0.15>
  }
  pigment { color rgb <0.75, 0.72, 0.65> }
  finish { diffuse 0.85 specular 0.2 roughness 0.05 }
}

// Red glass letters on the floor before it, kerned ("AV"): refraction, reflection and a
// coloured shadow.
text {
  ttf "timrom.ttf" "WAVE" 0.25, 0
  scale 0.7
  translate <-1.5, 0, -1.6>
  pigment { color rgbf <1, 0.35, 0.3, 0.85> }
  finish { specular 0.8 roughness 0.005 reflection { 0.05, 1 fresnel } conserve_energy }
  interior { ior 1.5 }
}

// Gold letters climbing a stair of offsets.
text {
  ttf "cyrvetic" "stairs" 0.12, <0.02, 0.08, 0>
  scale 0.45
  rotate -25 * y
  translate <0.6, 0, -2.3>
  pigment { color rgb <0.95, 0.7, 0.25> }
  finish { diffuse 0.5 specular 0.7 roughness 0.02 reflection 0.25 metallic }
}

// A rounded frame lying on the floor: two quadratic_spline contours, the inner one a hole.
prism {
  quadratic_spline
  0, 0.15, 12,
  <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>,
  <0, -0.55>, <0.55, 0>, <0, 0.55>, <-0.55, 0>, <0, -0.55>, <0.55, 0>
  scale 0.55
  translate <2.3, 0, -0.3>
  pigment { color rgb <0.25, 0.45, 0.9> }
  finish { diffuse 0.7 specular 0.5 roughness 0.02 }
}
