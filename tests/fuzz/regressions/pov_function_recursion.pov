camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#declare F = function(x) { F(x) + 1 }
#declare Y = F(1);
