camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1 }
mesh { triangle { <0/0,0,0>, <1,0,0>, <0,1,0> } triangle { 0, 0, 0 } pigment { rgb 1 } }
