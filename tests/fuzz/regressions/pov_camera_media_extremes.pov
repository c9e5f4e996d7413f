// Hostile media and a traced camera: a spherical camera at its widest (3600 by 3600 degrees),
// media of every container nested a few deep with the most steps (1024 per medium), 1e30
// emission and absorption, a density map of declared densities scaled to 1e-6 and 1e6, a
// solid object larger than its container, and a container the camera sits inside. It loads and
// renders with finite pixels, or stops with an error at its position; none crashes or hangs.
camera { spherical angle 3600, 3600 location <0, 0, -0.5> look_at 0 right x up y }
light_source { <0, 10, -10> color rgb 1 }
#declare D = density { spherical scale 1e-6 }
#declare E = density { bozo density_map { [0 D] [1 rgb 1e30] } scale 1e6 }
#declare M = media { emission 1e30 absorption 1e30 intervals 1e6 samples 1e6, 9 density { E } }
#for (I, 1, 4)
  sphere { 0, I pigment { rgbf 1 } hollow interior { media { M } media { emission <-1e30, 0, 1e30> } } }
#end
sphere { 0, 100 pigment { rgb 1 } hollow }
sphere { 3 * y, 0.5 pigment { rgb 1 } }
union { sphere { x, 1 } sphere { -x, 1 } pigment { rgbt 1 } hollow
        interior { media { emission 0.5 density { gradient x } density { D } } } }
