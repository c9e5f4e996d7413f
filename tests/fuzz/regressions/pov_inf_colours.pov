camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5> rgb 1e39 }
sphere { 0, 1 pigment { rgb <1e39, 0/0, -1e39> } finish { ambient 1e39 reflection 1e39 } }
