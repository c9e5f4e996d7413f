// Photon mapping (caustics): a spotlight over a white table; a clear glass ball focuses its
// light into a bright spot inside its own shadow, an amber glass ball a tinted one, and a
// polished steel ring throws the classic cardioid onto the table inside it. The balls and the
// ring are photon targets; the balls collect no photons themselves.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 6
  photons { spacing 0.01 jitter 0.4 }
}

camera { location <0, 7.5, -7> look_at <0, 0.3, 0.4> angle 45 }

light_source {
  <-7, 5.5, -2>, rgb 1.1
  spotlight point_at <0.5, 0, 0.5> radius 30 falloff 45
  photons { reflection on refraction on }
}
light_source { <4, 6, -6>, rgb 0.15 shadowless }

// The table.
plane { y, 0
  pigment { rgb <0.75, 0.73, 0.7> }
  finish { ambient 0.03 diffuse 0.8 }
}

#declare Glass = finish { ambient 0 diffuse 0 specular 0.6 roughness 0.002 reflection 0.04 }

// A clear ball.
sphere { <-1.6, 0.9, 0.4>, 0.9
  pigment { rgbf <1, 1, 1, 0.97> }
  finish { Glass }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off }
}

// An amber ball.
sphere { <0.4, 0.7, -1.3>, 0.7
  pigment { rgbf <1, 0.7, 0.25, 0.9> }
  finish { Glass }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}

// A steel ring: its inner wall reflects the light into a cardioid on the table.
difference {
  cylinder { <0, 0, 0>, <0, 0.8, 0>, 1.6 }
  cylinder { <0, -0.1, 0>, <0, 0.9, 0>, 1.5 }
  translate <1.6, 0, 1.6>
  pigment { rgb <0.8, 0.8, 0.82> }
  finish { ambient 0.02 diffuse 0.1 specular 0.5 roughness 0.01 reflection 0.85 metallic }
  photons { target reflection on refraction off }
}
