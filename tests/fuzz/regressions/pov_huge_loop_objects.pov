camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#declare I = 0;
#while (I < 1e9)
  sphere { I, 1 }
  #declare I = I + 1;
#end
