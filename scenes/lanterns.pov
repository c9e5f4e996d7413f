// Lanterns: glowing interior media seen through a wide cylinder camera. Five glass globes hold
// media that give off light through a spherical density (the middle one also absorbs, so its
// far side darkens), the last one a solid brass ball that its media leave out (objects are
// solid unless `hollow`). A `cylinder 1` camera spans 150 degrees across the row: straight
// lines up stay straight, the floor's lines across bend.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera {
  cylinder 1
  angle 150
  location <0, 1.6, -5>
  look_at <0, 1.2, 0>
  right x * image_width / image_height
}

light_source { <-4, 8, -6> rgb 0.9 }
background { rgb <0.02, 0.02, 0.05> }

plane { y, 0
  pigment { checker rgb 0.25 rgb 0.45 scale 0.8 }
  finish { reflection 0.1 }
}

#declare Glow = density {
  spherical
  color_map { [0 rgb 0] [0.3 rgb <0.6, 0.2, 0.05>] [1 rgb <1, 0.8, 0.3>] }
}

#macro Lantern(X, Z, Tint, Absorb)
  sphere { 0, 1
    pigment { rgbf <1, 1, 1, 1> }
    finish { ambient 0 diffuse 0 phong 0.6 phong_size 80 }
    interior {
      media {
        emission Tint
        absorption Absorb
        samples 12
        density { Glow }
      }
    }
    hollow
    scale 0.7
    translate <X, 1.2, Z>
  }
  cylinder { <X, 0, Z>, <X, 0.5, Z>, 0.06 pigment { rgb 0.2 } finish { phong 0.4 } }
#end

Lantern(-3.2, 1.5, rgb <1.6, 1.0, 0.5>, 0)
Lantern(-1.6, 0.6, rgb <0.6, 1.4, 0.9>, 0)
Lantern(0, 0, rgb <1.8, 1.2, 0.8>, rgb <0.2, 0.8, 1.5>)
Lantern(1.6, 0.6, rgb <0.8, 0.9, 1.8>, 0)
Lantern(3.2, 1.5, rgb <1.6, 0.6, 1.2>, 0)

// A solid brass ball inside the last lantern: the media around it leave it out.
sphere { <3.2, 1.2, 1.5>, 0.3
  pigment { rgb <0.8, 0.6, 0.2> }
  finish { ambient 0.1 diffuse 0.6 specular 0.6 roughness 0.02 reflection 0.3 }
}
