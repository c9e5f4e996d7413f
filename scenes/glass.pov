// Glass: refraction with an index of refraction (ior), Fresnel reflection that grows towards
// grazing angles, coloured glass that filters the light it lets through (its shadow is
// coloured too), and glass that darkens with the distance travelled inside it (interior fade).
//
//   render scenes/glass.pov -W 640 -H 480 -o glass.png
//   povray +Iscenes/glass.pov +W640 +H480 +A +Oglass.png
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 10 // light passes through several glass surfaces
}

camera {
  location <0, 2.8, -9>
  look_at <0, 0.6, 0>
  right x * image_width / image_height
  angle 42
}

light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 6, -3> color rgb 0.35 } // a fill light from the right

// A pale sky, darker overhead: the glass reflects and refracts it.
sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgb <0.85, 0.88, 0.95>] [0.5 rgb <0.45, 0.6, 0.85>] [1 rgb <0.25, 0.4, 0.75>] }
  }
}

// A checkered floor: straight lines show how each glass bends the view.
plane {
  y, 0
  pigment { checker rgb <0.9, 0.88, 0.82> rgb <0.2, 0.3, 0.45> scale 0.5 }
  finish { ambient 0.15 diffuse 0.75 }
}

// Coloured posts behind the glass, to be seen through it.
#declare Post_Colors = array[5] {
  <0.9, 0.2, 0.15>, <0.95, 0.7, 0.1>, <0.2, 0.7, 0.25>, <0.15, 0.4, 0.9>, <0.6, 0.25, 0.8>
}
#for (I, 0, 4)
  cylinder {
    <-3 + 1.5 * I, 0, 3>, <-3 + 1.5 * I, 2.2, 3>, 0.25
    pigment { rgb Post_Colors[I] }
    finish { ambient 0.1 diffuse 0.8 phong 0.4 }
  }
#end

// The finish of all the glass: no diffuse light of its own, a sharp highlight, and a
// reflection of 5% when seen face-on rising to 100% at grazing angles (Fresnel's law with the
// interior's ior); conserve_energy takes the reflected light from the transmitted.
#declare Glass_Finish = finish {
  ambient 0
  diffuse 0
  specular 0.7
  roughness 0.002
  reflection { 0.05, 1 fresnel on }
  conserve_energy
}

// Clear crown glass, ior 1.5: the sphere turns the checker upside down.
sphere {
  <-2.1, 1, 0>, 1
  pigment { rgbf <0.98, 0.98, 0.98, 0.95> }
  finish { Glass_Finish }
  interior { ior 1.5 }
}

// Blue filtering glass: filter 0.9 lets 90% of the light through, tinted by its colour, so its
// shadow on the floor is blue.
sphere {
  <0, 0.8, -0.6>, 0.8
  pigment { rgbf <0.35, 0.6, 1, 0.9> }
  finish { Glass_Finish }
  interior { ior 1.5 }
}

// Ruby glass that fades with depth: clear at the rims, deep red where the light crosses most
// glass (fade_power 1001 is POV-Ray's exponential absorption).
box {
  <-0.75, 0, -0.75>, <0.75, 1.5, 0.75>
  rotate y * 30
  translate <2.1, 0, 0.3>
  pigment { rgbf <1, 1, 1, 1> }
  finish { Glass_Finish }
  interior { ior 1.5 fade_distance 0.6 fade_power 1001 fade_color <0.9, 0.1, 0.2> }
}

// Small drops of water (ior 1.33) in front.
#for (I, 0, 2)
  sphere {
    <-0.9 + 0.9 * I, 0.25, -2>, 0.25
    pigment { rgbf <0.95, 1, 0.98, 0.97> }
    finish { Glass_Finish }
    interior { ior 1.33 }
  }
#end
