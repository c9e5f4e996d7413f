// Sky and fog: an avenue of columns on a checkered plain that runs to the horizon, under a sky
// sphere (a gradient from a pale horizon to a deep blue zenith, with a layer of clouds over
// it), fading into a constant fog. The fog's colour has some transmit, so that some of the
// sky still shows through it at the horizon.
//
//   render scenes/sky_fog.pov -W 640 -H 480 -o sky_fog.png
//   povray +Iscenes/sky_fog.pov +W640 +H480 +A +Osky_fog.png
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
  location <1.2, 1.6, -6>
  look_at <0, 2.6, 10>
  right x * image_width / image_height
  angle 60
}

// A low sun behind the camera, to the left.
light_source { <-300, 250, -400> color rgb <1, 0.93, 0.8> }

// ---- The sky: two layers; the clouds are clear where the bozo pattern is low ----
sky_sphere {
  pigment {
    gradient y
    color_map {
      [0.0 rgb <0.9, 0.85, 0.75>]
      [0.15 rgb <0.55, 0.68, 0.9>]
      [0.6 rgb <0.15, 0.3, 0.7>]
      [1.0 rgb <0.08, 0.15, 0.5>]
    }
  }
  pigment {
    bozo
    color_map {
      [0.0 rgbt <1, 1, 1, 1>]
      [0.55 rgbt <1, 1, 1, 1>]
      [0.75 rgbt <1, 1, 1, 0.35>]
      [1.0 rgbt <0.9, 0.9, 0.95, 0.1>]
    }
    scale <0.25, 0.06, 0.25>
  }
}

// ---- The fog: light fades to the fog colour over about `distance` units ----
fog {
  distance 55
  color rgbt <0.8, 0.82, 0.86, 0.5>
}

// ---- The plain: a checker that runs to the horizon ----
plane {
  y, 0
  pigment { checker rgb <0.85, 0.8, 0.7> rgb <0.35, 0.45, 0.3> scale 2 }
  finish { ambient 0.2 diffuse 0.75 }
}

// ---- The avenue: pairs of columns every 6 units, each with a ball on top ----
#declare Column_Texture = texture {
  pigment { rgb <0.92, 0.9, 0.85> }
  finish { ambient 0.2 diffuse 0.75 phong 0.3 }
}
#for (I, 0, 14)
  #for (Side, -1, 1, 2)
    union {
      cylinder { <0, 0, 0>, <0, 3.6, 0>, 0.3 }
      box { <-0.45, 0, -0.45>, <0.45, 0.3, 0.45> }  // plinth
      box { <-0.42, 3.6, -0.42>, <0.42, 3.85, 0.42> } // capital
      sphere { <0, 4.2, 0>, 0.35 }
      texture { Column_Texture }
      translate <Side * 3.5, 0, 4 + 6 * I>
    }
  #end
#end

// Coloured balls along the avenue, each further one deeper in the fog.
#declare Ball_Colors = array[5] {
  <0.9, 0.15, 0.1>, <0.95, 0.65, 0.1>, <0.2, 0.7, 0.25>, <0.15, 0.35, 0.9>, <0.6, 0.2, 0.75>
}
#for (I, 0, 4)
  sphere {
    <(mod(I, 2) * 2 - 1) * 1.3, 0.8, 6 + 10 * I>, 0.8
    pigment { rgb Ball_Colors[I] }
    finish { ambient 0.15 diffuse 0.75 phong 0.6 phong_size 60 }
  }
#end
