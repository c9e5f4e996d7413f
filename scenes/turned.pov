// Turned shapes: profiles turned about an axis (POV-Ray's lathe and sor), exact. A chess pawn
// (a cubic_spline lathe from the axis to the axis, a solid), a glass goblet (a sor: its radius
// squared a cubic in the height, closed by flat caps), a copper bowl whose curve does not close
// (only its surface, seen from inside and out), a ring of round section (a bezier_spline
// circle) and a vase cut open by a box (a lathe in a difference: its inside is a solid too).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 3.2, -7.5>
  look_at <0, 0.9, 0>
  right x * image_width / image_height
  angle 42
}
light_source { <-6, 9, -7> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.35 }
background { color rgb <0.55, 0.62, 0.72> }

plane {
  y, 0
  pigment { checker color rgb 0.85 color rgb 0.55 scale 0.6 }
  finish { diffuse 0.8 reflection 0.1 }
}

// A pawn: base, collar and head in one Catmull-Rom curve; the first and last points only
// steer it.
lathe {
  cubic_spline 14,
  <0, -0.1>, <0, 0>, <0.62, 0>, <0.6, 0.18>, <0.42, 0.3>, <0.3, 0.62>, <0.22, 1.0>,
  <0.38, 1.08>, <0.2, 1.16>, <0.3, 1.4>, <0.22, 1.66>, <0.08, 1.76>, <0, 1.78>, <0, 1.9>
  pigment { color rgb <0.12, 0.1, 0.09> }
  finish { diffuse 0.6 specular 0.6 roughness 0.01 reflection 0.12 }
  translate <-2.2, 0, 0.4>
}

// A goblet of glass: foot, stem and cup (the sor's heights rise from point to point).
sor {
  11,
  <0.5, -0.1>, <0.55, 0>, <0.5, 0.06>, <0.1, 0.15>, <0.07, 0.5>, <0.12, 0.8>,
  <0.45, 1.0>, <0.58, 1.3>, <0.6, 1.6>, <0.56, 1.8>, <0.5, 2.0>
  pigment { color rgbf <0.85, 0.95, 1, 0.9> }
  finish { specular 0.8 roughness 0.003 reflection { 0.05, 1 fresnel } conserve_energy }
  interior { ior 1.5 }
  translate <-0.8, 0, -0.3>
}

// A bowl: a quadratic curve from the middle of its floor to its rim, not closed, so only the
// surface is drawn and its inside shows.
lathe {
  quadratic_spline 5,
  <-0.3, 0.05>, <0, 0.05>, <0.7, 0.2>, <0.9, 0.65>, <0.95, 0.8>
  pigment { color rgb <0.85, 0.45, 0.25> }
  finish { diffuse 0.5 specular 0.5 roughness 0.02 reflection 0.3 metallic }
  translate <0.75, 0, -1.4>
}

// A ring of round section lying on the floor: a circle of four cubic Bézier arcs.
#declare K = 0.5523 * 0.16;
lathe {
  bezier_spline 16,
  <0.76, 0.16>, <0.76, 0.16 + K>, <0.6 + K, 0.32>, <0.6, 0.32>,
  <0.6, 0.32>, <0.6 - K, 0.32>, <0.44, 0.16 + K>, <0.44, 0.16>,
  <0.44, 0.16>, <0.44, 0.16 - K>, <0.6 - K, 0>, <0.6, 0>,
  <0.6, 0>, <0.6 + K, 0>, <0.76, 0.16 - K>, <0.76, 0.16>
  pigment { color rgb <0.95, 0.75, 0.3> }
  finish { diffuse 0.45 specular 0.8 roughness 0.01 reflection 0.35 metallic }
  translate <2.3, 0, -1.2>
}

// A vase with thick walls, the front of its upper half cut away to show the solid between
// them.
difference {
  lathe {
    linear_spline 9,
    <0, 0>, <0.55, 0>, <0.75, 0.6>, <0.4, 1.4>, <0.5, 1.8>, <0.42, 1.8>, <0.3, 1.4>,
    <0.62, 0.6>, <0, 0.12>
  }
  box { <-1, 0.7, -1>, <1, 2, 0> rotate 25 * y }
  pigment { color rgb <0.3, 0.5, 0.8> }
  finish { diffuse 0.75 specular 0.3 roughness 0.03 }
  translate <1.9, 0, 0.9>
}
