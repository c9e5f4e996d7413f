camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#fopen F "/dev/zero" read
#read (F, X)
