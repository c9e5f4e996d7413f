// Lights: a soft area light, three coloured spotlights whose pools of light add up to white
// (and whose shadows come out in the colours of the other two), a parallel moonlight, a ring
// of eight small coloured lamps whose light fades with distance, and a shadowless fill light.
// 23 light sources in all (Sheaf turns the area light into 4 x 4 point lights).
//
//   render scenes/lights.pov -W 640 -H 480 -o lights.png
//   povray +Iscenes/lights.pov +W640 +H480 +A +Olights.png
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4.2, -9>
  look_at <0, 0.9, 0.6>
  right x * image_width / image_height
  angle 48
}
background { rgb 0 }

// ---- The stage: a pale floor and back wall, white objects that show the lights' colours ----
#declare White = texture {
  pigment { rgb 0.85 }
  finish { ambient 0.02 diffuse 0.85 phong 0.3 phong_size 40 }
}
plane { y, 0 texture { White } }
plane { z, 4 texture { White } }

// Left: a ball in a ring of lamps.
sphere { <-2.4, 0.8, 0.4>, 0.8 texture { White } }
// Right: a column and a ball under the spotlights.
cylinder { <2.1, 0, 0.9>, <2.1, 2, 0.9>, 0.25 texture { White } }
sphere { <2.1, 2.3, 0.9>, 0.3 texture { White } }
sphere { <3, 0.45, -0.4>, 0.45 texture { White } }

// ---- An area light: a 1.5 x 1.5 square of 4 x 4 lights, for soft shadows ----
light_source {
  <-3, 7, -4>
  color rgb <1, 0.88, 0.7> * 0.25
  area_light <1.5, 0, 0>, <0, 0, 1.5>, 4, 4
  adaptive 1
  jitter
}

// ---- Three spotlights, red, green and blue, from different sides: where their pools
// overlap the colours add up (yellow, cyan, magenta, white) ----
#macro Spot(Position, Color, Target)
  light_source {
    Position
    color Color
    spotlight
    point_at Target
    radius 9
    falloff 14
    tightness 3
  }
#end
Spot(<0.3, 7, -2>, rgb <1, 0.05, 0.05>, <1.7, 0, 0.1>)
Spot(<2.3, 7, -3>, rgb <0.05, 1, 0.05>, <2.4, 0, 1.2>)
Spot(<4.3, 7, -2>, rgb <0.05, 0.05, 1>, <3.1, 0, 0.1>)

// ---- Moonlight: parallel rays from the upper right, a faint blue ----
light_source {
  <10, 12, -6>
  color rgb <0.08, 0.1, 0.2>
  parallel
  point_at <0, 0, 0>
}

// ---- Eight small lamps around the left ball: each a point light that fades with distance
// (fade_distance 0.7, fade_power 2) in a glowing bead that casts no shadow of its own ----
#declare Lamp_Colors = array[8] {
  <1, 0.3, 0.2>, <1, 0.7, 0.2>, <0.9, 1, 0.2>, <0.3, 1, 0.4>,
  <0.2, 0.9, 1>, <0.3, 0.45, 1>, <0.7, 0.3, 1>, <1, 0.3, 0.8>
}
#for (I, 0, 7)
  #declare Position = <-2.4, 0.15, 0.4> + vrotate(<1.35, 0, 0>, y * 45 * I);
  light_source {
    Position
    color rgb Lamp_Colors[I]
    fade_distance 0.7
    fade_power 2
  }
  sphere {
    Position, 0.07
    pigment { rgb Lamp_Colors[I] }
    finish { ambient 0 diffuse 0 emission 1 }
    no_shadow
  }
#end

// ---- A dim fill light from the camera that casts no shadows ----
light_source { <0, 5, -12> color rgb 0.06 shadowless }
