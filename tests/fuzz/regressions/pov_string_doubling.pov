camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#declare S = "ab";
#while (1)
  #declare S = concat(S, S);
#end
