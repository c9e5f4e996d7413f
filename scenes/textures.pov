// Procedural textures: twelve balls, each with its own pattern, on a floor of hexagonal tiles
// before a brick wall.
//
//   back row:   marble, wood, granite, agate           (colour maps, turbulence)
//   middle row: bozo, crackle, pigment_map, layers     (a map of pigments, a layered texture)
//   front row:  texture_map, bumps, ripples, wrinkles  (textures by pattern, normal patterns)
//
//   render scenes/textures.pov -W 640 -H 480 -o textures.png
//   povray +Iscenes/textures.pov +W640 +H480 +A +Otextures.png
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5.6, -11.5>
  look_at <0, 0.5, 0.3>
  right x * image_width / image_height
  angle 42
}

light_source { <-8, 12, -9> color rgb 0.95 }
light_source { <9, 7, -6> color rgb 0.3 shadowless } // fill light
background { rgb <0.6, 0.7, 0.85> }

// ---- The floor: hexagon tiles in three colours; the wall: brick ----
plane {
  y, 0
  pigment { hexagon rgb <0.72, 0.68, 0.6>, rgb <0.56, 0.52, 0.46>, rgb <0.42, 0.4, 0.37> scale 0.6 }
  finish { ambient 0.1 diffuse 0.75 }
}
plane {
  z, 4
  pigment {
    brick rgb <0.82, 0.8, 0.74>, rgb <0.62, 0.24, 0.14>
    brick_size <0.75, 0.25, 0.5>
    mortar 0.03
  }
  finish { ambient 0.12 diffuse 0.7 }
}

// A ball of the given texture in row Row (0 front, 2 back) and column Column (0 to 3).
#declare Radius = 0.8;
#macro Ball(Column, Row, Tex)
  sphere {
    0, Radius
    texture { Tex }
    translate <-3.3 + 2.2 * Column, Radius, -2.4 + 2.4 * Row>
  }
#end

#declare Shiny = finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 60 }

// ---- Back row: continuous patterns through colour maps ----
// White marble with dark veins: turbulence bends the pattern's stripes.
Ball(0, 2, texture {
  pigment {
    marble
    turbulence 1.4
    color_map {
      [0.0 rgb <0.95, 0.93, 0.9>]
      [0.6 rgb <0.86, 0.84, 0.82>]
      [0.85 rgb <0.45, 0.45, 0.5>]
      [1.0 rgb <0.15, 0.15, 0.2>]
    }
    scale 0.7
    rotate z * 40
  }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 90 reflection 0.08 }
})
// Wood: rings around the z axis, cut along their length by tipping the pattern.
Ball(1, 2, texture {
  pigment {
    wood
    turbulence 0.06
    color_map {
      [0.0 rgb <0.8, 0.55, 0.28>]
      [0.6 rgb <0.66, 0.4, 0.18>]
      [1.0 rgb <0.45, 0.25, 0.1>]
    }
    scale 0.15
    rotate x * 75
  }
  finish { Shiny }
})
// Granite: fractal noise, speckled.
Ball(2, 2, texture {
  pigment {
    granite
    color_map {
      [0.0 rgb <0.9, 0.86, 0.84>]
      [0.35 rgb <0.75, 0.6, 0.56>]
      [0.6 rgb <0.35, 0.32, 0.33>]
      [1.0 rgb 0.08]
    }
    scale 1.2
  }
  finish { Shiny }
})
// Agate: bands bent by noise.
Ball(3, 2, texture {
  pigment {
    agate
    color_map {
      [0.0 rgb <0.95, 0.8, 0.55>]
      [0.4 rgb <0.85, 0.45, 0.15>]
      [0.7 rgb <0.55, 0.2, 0.08>]
      [1.0 rgb <0.98, 0.92, 0.8>]
    }
    scale 0.6
  }
  finish { Shiny }
})

// ---- Middle row ----
// Bozo: smooth noise as white clouds in a blue sky.
Ball(0, 1, texture {
  pigment {
    bozo
    turbulence 0.4
    color_map { [0.3 rgb <0.2, 0.4, 0.9>] [0.7 rgb <0.97, 0.97, 1>] }
    scale 0.35
  }
  finish { ambient 0.15 diffuse 0.75 }
})
// Crackle: cells, here dried mud with dark cracks along the cell borders.
Ball(1, 1, texture {
  pigment {
    crackle
    color_map {
      [0.0 rgb <0.12, 0.08, 0.05>]
      [0.05 rgb <0.12, 0.08, 0.05>]
      [0.12 rgb <0.7, 0.52, 0.3>]
      [1.0 rgb <0.85, 0.7, 0.45>]
    }
    scale 0.25
  }
  finish { ambient 0.1 diffuse 0.8 }
})
// A pigment map: a gradient from a red checker at the bottom to blue radial stripes at the
// top, each of the two a pigment of its own.
Ball(2, 1, texture {
  pigment {
    gradient y
    pigment_map {
      [0.35 checker rgb <0.85, 0.1, 0.1>, rgb 0.95 scale 0.2]
      [0.65 radial frequency 12 color_map { [0.5 rgb <0.1, 0.3, 0.85>] [0.5 rgb 0.95] }]
    }
    scale 2 * Radius
    translate -Radius * y
  }
  finish { Shiny }
})
// A layered texture: leopard spots (clear between them) over a cream base.
Ball(3, 1, texture {
  pigment { rgb <0.93, 0.82, 0.55> }
  finish { Shiny }
}
texture {
  pigment {
    leopard
    color_map { [0.0 rgbt 1] [0.45 rgbt 1] [0.5 rgb <0.3, 0.15, 0.05>] [1.0 rgb <0.1, 0.05, 0.02>] }
    scale 0.09
  }
  finish { Shiny } // lit as the base is (Sheaf lights a layered texture with one finish)
})

// ---- Front row ----
// A texture map: bands alternate between polished gold and matte dark red, finish and all.
#declare Gold = texture {
  pigment { rgb <0.95, 0.72, 0.3> }
  finish { ambient 0.05 diffuse 0.4 specular 0.8 roughness 0.005 metallic reflection { 0.5 metallic } }
}
#declare Matte = texture {
  pigment { rgb <0.45, 0.06, 0.08> }
  finish { ambient 0.1 diffuse 0.8 }
}
Ball(0, 0, texture {
  gradient y
  texture_map { [0.5 Gold] [0.5 Matte] } // a step: POV-Ray blends only between two values
  scale 0.5
})
// Normal patterns tilt the shading normal: bumps ...
Ball(1, 0, texture {
  pigment { rgb <0.6, 0.7, 0.85> }
  normal { bumps 0.6 scale 0.12 }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 80 }
})
// ... ripples, rings of waves spreading from a point ...
Ball(2, 0, texture {
  pigment { rgb <0.2, 0.6, 0.65> }
  normal { ripples 0.7 frequency 3 translate <0.3, 1, -0.5> }
  finish { ambient 0.1 diffuse 0.7 phong 0.9 phong_size 120 reflection 0.15 }
})
// ... and wrinkles.
Ball(3, 0, texture {
  pigment { rgb <0.45, 0.7, 0.3> }
  normal { wrinkles 0.9 scale 0.4 }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 }
})
