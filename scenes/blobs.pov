// Blobs, and the scene language's trace() and inside(): a wax candle shaped by negative
// components, a molecule cut open by a box, a grassy mound with pebbles dropped onto it by
// trace(), and a ring of bubbles kept where inside() finds them within a torus.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4.2, -9>
  look_at <0, 1.1, 1>
  angle 52
  right x * image_width / image_height
}
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -6> rgb 0.35 shadowless }
plane { y, 0 pigment { checker rgb 0.75 rgb 0.55 } }

// A candle: a cylinder component with round ends, hollowed at the top and flattened at the
// bottom by negative spheres, a notch where wax runs over and a drop below it.
blob {
  threshold 0.5
  cylinder { <0, 0, 0>, <0, 2, 0>, 1, 1 }
  sphere { <0, 2.5, 0>, 0.8, -2 }
  sphere { <0, -0.52, 0>, 0.8, -2 }
  sphere { <0, 2, -0.5>, 0.1, -0.2 }
  cylinder { <0, 1.88, -0.52>, <0, 1.5, -0.52>, 0.05, 0.2 }
  sphere { <0, 1.5, -0.55>, 0.07, 0.2 }
  pigment { rgb <0.85, 0.55, 0.08> }
  finish { specular 0.4 roughness 0.02 }
  translate <-3.2, 0, 1.5>
}

// A molecule: two atoms, a bond, and a lobe that is a sphere component scaled into an
// ellipsoid; its front half cut away by a box, so the inside shows.
difference {
  blob {
    threshold 0.4
    sphere { <-0.8, 0, 0>, 1.1, 1 }
    sphere { <0.8, 0, 0>, 1.1, 1 }
    cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.5, 1 }
    sphere { 0, 1, 1 scale <0.4, 1.4, 0.4> translate <0, 0.6, 0> }
    pigment { rgb <0.2, 0.4, 0.9> }
    finish { phong 0.6 }
  }
  box { <-2, -2, -2>, <2, 2, 0> pigment { rgb <1, 0.85, 0.5> } }
  rotate y * 50
  translate <-0.6, 1.1, 2.6>
}

// A mound of random spheres, and pebbles dropped onto it from above: trace() gives where
// each lands and the surface's normal there.
#declare R = seed(7);
#declare Mound = blob {
  threshold 0.6
  #for (I, 0, 24)
    sphere { <rand(R) * 2.4 - 1.2, 0, rand(R) * 2.4 - 1.2>, 0.9 + rand(R) * 0.5, 1 }
  #end
  pigment { rgb <0.3, 0.6, 0.25> }
  translate <3.2, 0, 1.2>
}
object { Mound }
#for (I, 0, 59)
  #declare From = <3.2 + rand(R) * 3 - 1.5, 5, 1.2 + rand(R) * 3 - 1.5>;
  #declare N = <0, 0, 0>;
  #declare Hit = trace(Mound, From, -y, N);
  #if (vlength(N) > 0)
    sphere { Hit + N * 0.07, 0.07 pigment { rgb <0.95, 0.92, 0.85> } }
  #end
#end

// A ring of bubbles: on a grid, a sphere component wherever inside() finds the point
// within a torus; the blob melts them into a lumpy ring.
#declare Ring = torus { 1, 0.4 rotate x * 90 }
blob {
  threshold 0.5
  #for (X, -1.5, 1.5, 0.25)
    #for (Y, -1.5, 1.5, 0.25)
      #if (inside(Ring, <X, Y, 0>))
        sphere { <X, Y, 0>, 0.32, 1 }
      #end
    #end
  #end
  pigment { rgb <0.9, 0.3, 0.35> }
  finish { specular 0.5 roughness 0.01 }
  translate <1.6, 1.6, 6>
}
