// Atmospheric media: a hazy hall lit through a window of four panes by a spotlight outside,
// so that four shafts of light cross the haze to the floor; a red lamp inside sends a narrow
// cone down over a solid ball (its shadow cuts the cone) and a clear glass ball that the haze
// leaves out (POV-Ray's objects are solid unless `hollow`). The hall and the sky are `hollow`:
// the haze fills them. The lamp's light fades through the haze on its way (`media_attenuation on`).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera { location <0, 3, -11> look_at <0, 2.2, 0> angle 62 }

media {
  scattering { 1, rgb 0.045 }
  absorption rgb 0.005
  intervals 2 samples 24
}

#declare Wall = texture { pigment { rgb <0.75, 0.72, 0.66> } finish { ambient 0.02 diffuse 0.7 } }

// The hall: a hollow box, its back wall pierced by a window of four panes.
difference {
  box { <-8, 0, -12>, <8, 7, 8> }
  box { <-7.8, 0.01, -11.8>, <7.8, 6.8, 7.8> }
  box { <-1.9, 2.6, 7.5>, <-0.1, 4.4, 8.5> }
  box { < 0.1, 2.6, 7.5>, < 1.9, 4.4, 8.5> }
  box { <-1.9, 4.6, 7.5>, <-0.1, 6.4, 8.5> }
  box { < 0.1, 4.6, 7.5>, < 1.9, 6.4, 8.5> }
  texture { Wall }
  hollow
}

// The sun outside, aimed through the window at the floor.
light_source {
  <0, 14, 22> color rgb <1.6, 1.5, 1.3>
  spotlight point_at <0, 0, 0> radius 12 falloff 16
}

// A red lamp hanging inside, its narrow cone over the solid ball.
light_source {
  <-3.5, 6.5, 1> color rgb <1.6, 0.35, 0.25>
  spotlight point_at <-3.5, 0, 1> radius 8 falloff 12
  media_attenuation on
}
sphere { <-3.5, 3.2, 1>, 0.25 pigment { rgb <1, 0.4, 0.3> } finish { emission 1 } no_shadow }

sphere { <-3.5, 1.1, 1>, 1.1 pigment { rgb <0.9, 0.85, 0.8> } finish { diffuse 0.8 phong 0.4 } }

sphere {
  <2.8, 1.2, -1.5>, 1.2
  pigment { rgbf <0.95, 1, 0.97, 0.95> }
  finish { reflection { 0.04, 0.4 fresnel } }
  interior { ior 1.5 }
}

// The sky outside, a hollow sphere: rays through the window cross the haze up to it (a ray
// that meets nothing would cross 2e10 units of haze, as in POV-Ray).
sphere { 0, 80 hollow pigment { rgb <0.55, 0.7, 0.95> } finish { ambient 1 diffuse 0 } no_shadow }

// A dim fill that lights the walls but not the haze.
light_source { <0, 6, -9> color rgb 0.25 shadowless media_interaction off }
