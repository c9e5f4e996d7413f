camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#declare A = array[100000000];
#declare B = array[100000000];
#declare C = array[100000000];
