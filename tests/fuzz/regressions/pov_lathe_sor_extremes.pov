// Hostile profiles: many points in a scramble, extreme and tiny coordinates, a bezier lathe
// with control points left of the axis, a sor squeezed into 1e-20 of height. Each loads and
// renders, or stops with an error at its position; none crashes or hangs.
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 10, -10> color rgb 1 }
#declare N = 3000;
lathe { linear_spline N,
#declare I = 0;
#while (I < N)
  <mod(I * 7919, 13) / 3, sin(I) * 2>,
  #declare I = I + 1;
#end
}
lathe { cubic_spline 5, <1e30, 0>, <1e20, 1>, <1e-30, 2>, <0, 3>, <0, 1e30> }
lathe { bezier_spline 8, <0, 0>, <-5, 1>, <-5, 2>, <0, 3>, <0, 3>, <1e-30, 3>, <1e-30, 3>, <0, 3> }
lathe { quadratic_spline 3, <0, 0>, <0, 0>, <0, 0> }
sor { 4, <0, 0>, <1e-20, 1e-20>, <1e-20, 2e-20>, <0, 3e-20> }
sor { 6, <1e3, -1>, <1, 0>, <1e3, 1e-9>, <1, 2e-9>, <1, 1>, <0, 3> open }
