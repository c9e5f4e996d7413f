// Hostile blobs: a thousand components on one spot and in a line (more than a ray follows),
// strengths of 1e30 and -1e30, a threshold of 1e-30, radii from 1e-6 to 1e18, components
// squashed almost flat, cylinders of no length. Each loads and renders, or stops with an error
// at its position; none crashes or hangs.
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 10, -10> color rgb 1 }
blob {
  threshold 1e-30
  #for (I, 0, 999)
    sphere { <0, 0, 0>, 1, 1 }
    sphere { <I * 0.01, 0, 0>, 0.5, -1 }
  #end
}
blob { threshold 1 sphere { 0, 1, 1e30 } sphere { x, 1, -1e30 } cylinder { 0, 0, 1, 1 } }
blob { sphere { 0, 1e-6, 1 } sphere { 0, 1e18, 1 } cylinder { 0, 1e18 * x, 2, 1 } }
blob { sphere { 0, 1, 5 scale <1, 1e-6, 1> } cylinder { -x, x, 1, 2 scale <1e-6, 1, 1e6> } }
