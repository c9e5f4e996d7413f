// Hostile fractal patterns and bicubic patches: the most iterations and the highest exponent
// on a large view, the magnet formulas at their poles (z = 0, c = 2), a julia constant of
// 1e30, factors of 1e30 and -1e30, exterior types 7 and 8 at their smallest and largest factors; patches
// whose points coincide, lie on a line, or lie 1e30 apart. Each loads and renders with finite
// pixels, or stops with an error at its position; none crashes or hangs.
camera { location <0, 0, -4> look_at 0 }
light_source { <0, 10, -10> color rgb 1 }
plane { z, 0
  pigment { mandel 2000 exponent 33 exterior 6, 1e30 interior 6, -1e30 scale 1e-3
            color_map { [0 rgb 0] [1 rgb 1] } }
  normal { magnet 1 mandel 500 1e30 interior 1, 1e30 translate <2, 0, 0> }
}
sphere { 0, 1 pigment { magnet 2 julia <1e30, -1e30> 100 exterior 7, 1e30 } }
sphere { x, 1 pigment { julia <2, 0> 300 exterior 8, 1e-30 } normal { julia <0, 0>, 300 } }
bicubic_patch { type 1 u_steps 99 v_steps -5
  #for (I, 0, 15) <1, 2, 3> #end }
bicubic_patch { type 0
  #for (I, 0, 15) <I, 0, 0> #end }
bicubic_patch { type 1
  #for (I, 0, 15) <mod(I, 4) * 1e30, 0, div(I, 4) * 1e30 - 1e30> #end pigment { rgb 1 } }
bicubic_patch { type 1
  #for (I, 0, 15) <mod(I, 4) * 1e-30, div(I, 4) * 1e-30, 0> #end }
