// Hostile height fields: functions that give NaN, infinity and 1e30, a grid of 2 x 2 and one of
// 300 x 300, a water level above everything and one below, a pigment function. Each loads and renders, or stops with an error at its position; none crashes
// or hangs.
camera { location <0.5, 2, -1> look_at <0.5, 0, 0.5> }
light_source { <0, 10, -10> color rgb 1 }
height_field { function 2, 2 { sqrt(-1) } smooth }
height_field { function 3, 3 { 1 / (x - 0.5) } water_level -1e30 }
height_field { function 300, 300 { 1e30 * sin(x * 100) } smooth translate x }
height_field { function 50, 50 { x } water_level 2 }
height_field { function 50, 50 { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } } }
