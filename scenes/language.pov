// The scene language: everything here is generated. A recursive macro grows a tree, a #while
// loop winds a spiral of metal balls whose textures a #switch picks, nested #for loops raise
// a field of bars whose heights come from a user function and whose colours come from a
// colors.inc macro, arrays hold the choices, and the textures come from POV-Ray's standard
// include files (colors.inc, textures.inc, woods.inc, stones.inc).
//
//   render scenes/language.pov -W 640 -H 480 -o language.png
//   povray +Iscenes/language.pov +W640 +H480 +A +Olanguage.png
#version 3.7;

#include "colors.inc"   // named colours (White, Gray30 ...) and colour macros (CHSV2RGB)
#include "textures.inc" // Gold_Metal, Silver_Metal, Copper_Metal, Brass_Metal, Jade ...
#include "woods.inc"    // T_Wood1 ... T_Wood35
#include "stones.inc"   // T_Stone1 ... T_Stone44, T_Grnt0 ... T_Grnt29

global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 3.4, -9.8>
  look_at <0, 1.5, 0.6>
  right x * image_width / image_height
  angle 46
}
light_source { <-7, 11, -8> color White }
light_source { <7, 6, -7> color Gray30 shadowless }
sky_sphere { pigment { Bright_Blue_Sky } } // a pigment of textures.inc

// A wooden floor: woods.inc's textures have their rings around z, so the floor shows the grain.
plane { y, 0 texture { T_Wood7 scale 2 rotate y * 90 } }

// Three stone pedestals, their textures taken from an array.
#declare Stones = array[3] { T_Stone1, T_Grnt9, T_Stone21 }
#declare Pedestal_X = array[3] { -3.1, 0, 3.1 }
#for (I, 0, 2)
  box {
    <-1.2, 0, -1.2>, <1.2, 0.3, 1.2>
    texture { Stones[I] scale 0.6 }
    translate <Pedestal_X[I], 0, 0.8>
  }
#end

// ---- Left: a tree grown by a recursive macro ----
#declare Bark = texture { T_Wood10 scale 0.1 }
#declare Leaf = texture { pigment { Jade scale 0.3 } finish { phong 0.4 } }
#declare Branches = 0;

// A branch from Base along the unit vector Dir; then, while Depth > 0, three shorter and
// thinner branches turned away from it, each drawn by the macro itself; a leaf at the end.
#macro Branch(Base, Dir, Len, Radius, Depth)
  #local K = 0; // declared local first: Sheaf's reader lets a #for change a caller's K
  #local Tip = Base + Dir * Len;
  cylinder { Base, Tip, Radius texture { Bark } }
  sphere { Tip, Radius texture { Bark } }
  #declare Branches = Branches + 1;
  #if (Depth > 0)
    #if (abs(Dir.y) < 0.99) #local Side = vnormalize(vcross(Dir, y));
    #else #local Side = x;
    #end
    #for (K, 0, 2)
      // Tilt 32 degrees away from the branch, then turn a third of the way round it.
      #local New_Dir = vaxis_rotate(vaxis_rotate(Dir, Side, 32), Dir, 120 * K + 50 * Depth);
      Branch(Tip, New_Dir, Len * 0.7, Radius * 0.62, Depth - 1)
    #end
  #else
    sphere { Tip, 0.13 texture { Leaf } }
  #end
#end
Branch(<-3.1, 0.3, 0.8>, y, 1.15, 0.12, 5)

// ---- Middle: a spiral of metal balls around a chrome post, by a #while loop ----
cylinder { <0, 0.3, 0.8>, <0, 3.2, 0.8>, 0.08 texture { Chrome_Metal } }
#declare N = 0;
#while (N < 26)
  #declare Position = vrotate(<1, 0.5 + N * 0.105, 0>, y * N * 32) + <0, 0, 0.8>;
  sphere {
    Position, 0.22 - N * 0.004
    texture {
      #switch (mod(N, 4))
        #case (0) Gold_Metal   #break
        #case (1) Silver_Metal #break
        #case (2) Copper_Metal #break
        #else     Brass_Metal
      #end
    }
  }
  #declare N = N + 1;
#end

// ---- Right: a field of bars; a function of two variables gives each bar its height ----
#declare Hill = function(A, B) { 0.2 + 0.45 * (1 + sin(2.1 * A) * cos(1.6 * B)) * (0.6 + 0.1 * A) }
#declare Bars = 0;
#for (I, 0, 9)
  #for (J, 0, 9)
    #declare H = Hill(I * 0.3, J * 0.3);
    box {
      <-0.09, 0, -0.09>, <0.09, H, 0.09>
      // colors.inc's CHSV2RGB: the hue runs from blue for low bars to red for high ones.
      pigment { color CHSV2RGB(<max(0, 250 - 220 * H), 0.8, 0.95>) }
      finish { ambient 0.1 diffuse 0.75 phong 0.5 }
      translate <3.1 - 0.98 + I * 0.218, 0.3, 0.8 - 0.98 + J * 0.218>
    }
    #declare Bars = Bars + 1;
  #end
#end

// Strings: a note on the console (POV-Ray's message stream, Sheaf's stderr).
#debug concat("language.pov: ", str(Branches, 0, 0), " branches, ", str(N, 0, 0),
              " balls, ", str(Bars, 0, 0), " bars\n")
