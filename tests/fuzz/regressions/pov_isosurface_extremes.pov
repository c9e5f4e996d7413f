// Hostile isosurfaces and function patterns: a max_gradient far too small and one of 1e30, an
// accuracy of 1e-30, functions that give NaN and infinity, a container of 1e18, a function of
// calls nested until the stack limit, and a function pattern that divides by zero. Each loads
// and renders, or stops with an error at its position; none crashes or hangs.
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 10, -10> color rgb 1 }
#declare F = function(a) { a * 2 + 1 }
#declare G = function(a) { F(F(F(F(a)))) }
#declare H = function(a) { G(G(G(G(a)))) }
isosurface { function { sin(x * 1000) * y } max_gradient 1e-6 accuracy 1e-30 }
isosurface { function { sqrt(-1 - x * x) } max_gradient 1e30 }
isosurface { function { 1 / (x * y * z) } contained_by { box { -1e18, 1e18 } } }
isosurface { function { H(x) - H(y) + pow(z, 1e6) } contained_by { sphere { 0, 1e-20 } } }
isosurface { function { log(0) * x } threshold -1e30 evaluate 1e30, 1, 1 open }
sphere { 0, 1 pigment { function { 1 / x } color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 normal { function { ln(-1) + x } 1e30 } }
