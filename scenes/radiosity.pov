// Radiosity (diffuse interreflection): a room lit by one lamp under the ceiling and a glowing
// panel, where the red and blue walls tint the white floor and ceiling beside them, the light
// bounces twice (recursion_limit 2) into the corners the lamp does not reach, and a mirror
// ball shows the room lit the same way (gathering also happens on mirror paths).
//
//   render scenes/radiosity.pov -W 640 -H 480 -o radiosity.png
//   povray +Iscenes/radiosity.pov +W640 +H480 -D +Oradiosity.png
//
// Sheaf gathers `count` rays at every pixel (no irradiance cache): the setting
// radiosity.samples=N trades noise for time (render ... --set radiosity.samples=16).
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 4
  radiosity {
    count 48
    recursion_limit 2
    brightness 1
    pretrace_start 0.08 pretrace_end 0.02 // POV-Ray's cache; Sheaf reads and ignores them
  }
}

camera {
  location <0, 1.5, -4.6>
  look_at <0, 1.15, 0>
  angle 64
  right x * image_width / image_height
}

#declare Matte = finish { diffuse 0.85 ambient 0 }
#declare White = texture { pigment { rgb <0.82, 0.8, 0.76> } finish { Matte } }
#declare Red = texture { pigment { rgb <0.75, 0.12, 0.08> } finish { Matte } }
#declare Blue = texture { pigment { rgb <0.1, 0.2, 0.7> } finish { Matte } }

// The room: 4 wide, 3 high, 6 deep, closed behind the camera.
box { <-2, -0.1, -5>, <2, 0, 2> texture { White } }    // floor
box { <-2, 3, -5>, <2, 3.1, 2> texture { White } }     // ceiling
box { <-2, 0, 2>, <2, 3, 2.1> texture { White } }      // back wall
box { <-2, 0, -5.1>, <2, 3, -5> texture { White } }    // wall behind the camera
box { <-2.1, 0, -5>, <-2, 3, 2> texture { Red } }      // left wall
box { <2, 0, -5>, <2.1, 3, 2> texture { Blue } }       // right wall

// The lamp: a small bulb under the ceiling, and a glowing panel on the back wall.
light_source {
  <0.3, 2.7, 0.2>
  color rgb <1, 0.95, 0.85> * 1.6
  fade_distance 2 fade_power 2
  looks_like { sphere { 0, 0.08 pigment { rgb 1 } finish { emission 1 diffuse 0 } } }
}
box {
  <-0.9, 1.6, 1.98>, <0.9, 2.2, 2>
  pigment { rgb <1, 0.85, 0.6> }
  finish { emission 0.9 diffuse 0 ambient 0 }
}

// A white cube, a tall block beside the red wall, and a mirror ball.
box { <-0.45, 0, -0.45>, <0.45, 0.9, 0.45> rotate y * 25 translate <0.7, 0, 0.6> texture { White } }
box { <-0.35, 0, -0.35>, <0.35, 1.8, 0.35> rotate y * -15 translate <-1.3, 0, 1.1> texture { White } }
sphere {
  <-0.5, 0.45, -0.6>, 0.45
  pigment { rgb 0.9 }
  finish { diffuse 0.05 ambient 0 reflection 0.85 phong 0.6 phong_size 80 }
}
