camera { location <0,0,-5> look_at 0 }
#declare F = function(x,y,z) { x }
#declare I = 0;
#while (I < 100000)
  #declare F = function(x,y,z) { F(x,y,z) + 1 }
  #declare I = I + 1;
#end
#declare Y = F(1,1,1);
