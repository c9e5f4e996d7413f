camera { location <0,0,-5> direction 0 up 0 right 0 }
light_source { <5,5,-5> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
