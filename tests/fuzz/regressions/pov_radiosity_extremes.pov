// Radiosity at its limits: the most bounces, the greatest brightness, an area light of 400
// samples (gathered points take 4 of them), an emissive wall, glass and mirrors on gathered
// paths. Must render finite pixels in a few seconds at the fuzzers' 24 x 16.
#version 3.7;
global_settings {
  max_trace_level 10
  radiosity { count 300, 1600 recursion_limit 8 brightness 100 gray_threshold 0
              nearest_count 20, 10 always_sample on max_sample -1 adc_bailout 0 }
}
camera { location <0, 1, -3> look_at <0, 0.5, 0> right -x }
light_source { <0, 2.5, 0> rgb 1 area_light x, z, 20, 20 spotlight radius -90 falloff 90 tightness 0 }
box { <-2, -0.1, -4>, <2, 3, 2> hollow pigment { rgb 0.99 } finish { diffuse 1 ambient 1 } }
plane { z, 1.9 pigment { rgb <1e3, 0, 0> } finish { emission 1 diffuse 0 } }
sphere { <-0.6, 0.4, 0>, 0.4 pigment { rgbf <1, 1, 1, 0.9> } finish { reflection 1 diffuse 1 } interior { ior 1.5 } }
sphere { <0.6, 0.4, 0>, 0.4 pigment { rgb 1 } finish { reflection { 1 metallic } diffuse 1 } }
