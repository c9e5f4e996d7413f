// Voxel files (`density_file df3`): a glowing nebula whose emitting and absorbing medium is
// read from textures/nebula.df3 (20 x 20 x 20 bytes: a ring with three twisted arms) with
// trilinear interpolation, and a slab of marble-like stone coloured by the same file read
// tricubically (`interpolate 2`) through a colour map, on a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -7> look_at <0, 0.9, 0> angle 48 }
light_source { <4, 9, -6> color rgb 1 }
background { rgb <0.02, 0.02, 0.05> }

plane {
  y, 0
  pigment { checker rgb 0.55 rgb 0.35 scale 0.8 }
  finish { diffuse 0.8 }
}

// The nebula: the file spans the unit cube, moved to be centred and scaled up.
box {
  0, 1
  pigment { rgbt 1 }
  hollow
  interior {
    media {
      emission rgb <2.2, 1.1, 3.2>
      absorption rgb <0.3, 0.6, 0.9>
      density { density_file df3 "textures/nebula.df3" interpolate 1 }
      samples 24
    }
  }
  translate -0.5 scale <3.2, 1.6, 3.2> rotate -35 * x translate <-1.3, 1.6, 1>
}

// A slab coloured by the file read tricubically: the ring's slice through its middle, stood up.
box {
  <0, 0.48, 0>, <1, 0.52, 1>
  pigment {
    density_file df3 "textures/nebula.df3" interpolate 2
    color_map { [0 rgb <0.15, 0.12, 0.1>] [0.5 rgb <0.8, 0.5, 0.3>] [1 rgb <1, 0.95, 0.85>] }
  }
  finish { diffuse 0.8 specular 0.3 }
  translate -0.5 rotate -90 * x scale 1.8 rotate 30 * y translate <1.9, 1.05, 0.3>
}
