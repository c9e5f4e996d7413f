camera { location 0 look_at 0 }
light_source { <5,5,-5> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
