// The built-in scene "colonnade" (core/scenes/builtin_colonnade.cpp) in POV-Ray's language: a
// Sponza-like courtyard of 66,000 triangles in one single mesh: a paved floor, two storeys of
// arcades on both long sides (turned columns with plinths and abaci, arches, a balustrade),
// gallery floors and roofs, end walls, and the open sky over the courtyard.
//
//   render scenes/colonnade.pov -W 640 -H 480 -o colonnade.png  (as builtin:colonnade)
//   povray +Iscenes/colonnade.pov +W640 +H480 -D +Ocolonnade.png
//
// Coordinates are the C++ scene's with z negated (POV-Ray is left-handed; see shapes.inc):
// the camera stands at z = +17 and looks down the courtyard towards -z.
#version 3.7;
#include "shapes.inc"

global_settings { assumed_gamma 1.0 }

// The courtyard spans x in [-HalfX, HalfX] and z in [-HalfZ, HalfZ]; the arcades stand on
// x = +-ArcadeX, with bays of Bay between column centres.
#declare HalfX = 10;
#declare HalfZ = 20;
#declare ArcadeX = 6;
#declare Bay = 4;
#declare Columns = 10; // per arcade line
#declare WallT = 0.3;
#declare Abacus = 0.35;
#declare ArchDepth = 0.7;
#declare ColumnSegments = 24;
#declare ArchSegments = 24;
#declare BalusterSegments = 10;

// The storeys' heights.
#declare Ground = 4;       // ground-floor columns
#declare GroundArch = 2;   // ground-floor arches
#declare Slab = 0.35;      // gallery floors and the roof
#declare Upper = 3.2;      // upper columns
#declare UpperArch = 1.8;  // upper arches
#declare Floor2 = Ground + GroundArch + Slab; // the upper gallery's floor
#declare Top = Floor2 + Upper + UpperArch + Slab;

camera {
  perspective
  location <0, 1.7, 17>
  up y
  right x * image_width / image_height
  direction z * 0.5 / tan(radians(55 / 2)) // a 55 degree vertical field of view
  look_at <0, 4, -20>
}
light_source { <2, Top - 0.5, 4> color rgb 1 } // the sun, low over the courtyard's roofs
background { rgb 0 }

#declare Stone = texture {
  pigment { rgb <0.78, 0.72, 0.62> }
  finish { ambient 0.1 diffuse 0.7 phong 0.05 phong_size 40 }
}

// The z of column K of a line (the C++ column_z, negated).
#macro ColumnZ(K) (Bay * (Columns - 1) / 2 - Bay * K) #end

// A column standing at Foot, Height tall: a square plinth, a turned shaft and an abacus.
#macro Column(Foot, Height)
  #local Plinth = 0.2;
  #local AbacusH = 0.15;
  #local L = Height - Plinth - AbacusH;
  Sh_Box(Foot + <-0.4, 0, -0.4>, Foot + <0.4, Plinth, 0.4>)
  #local Profile = array[13] {
    <0.34, 0>,         <0.36, 0.04>,      <0.36, 0.10>,      <0.31, 0.14>,
    <0.27, 0.20>,      <0.26, 0.5 * L>,   <0.24, L - 0.35>,  <0.265, L - 0.32>,
    <0.265, L - 0.28>, <0.24, L - 0.25>,  <0.30, L - 0.12>,  <0.38, L - 0.02>,
    <0.38, L>
  }
  Sh_Lathe(Foot + <0, Plinth, 0>, y, Profile, ColumnSegments)
  Sh_Box(Foot + <-Abacus, Height - AbacusH, -Abacus>, Foot + <Abacus, Height, Abacus>)
#end

// One storey of an arcade on x = X0: columns from Y0 to Y0 + ColumnHeight, arches above them
// up to Y0 + ColumnHeight + ArchHeight, and piers that join the ends to the end walls.
#macro Arcade(X0, Y0, ColumnHeight, ArchHeight)
  #local K = 0; #local S = 0; // loop variables, local (see shapes.inc)
  #local Spring = Y0 + ColumnHeight;
  #for (K, 0, Columns - 1)
    Column(<X0, Y0, ColumnZ(K)>, ColumnHeight)
  #end
  // An arch is made in the x-y plane; a quarter turn makes it run along z.
  #for (K, 0, Columns - 2)
    #local From = Sh_NP;
    Sh_Arch(<0, 0, 0>, Bay / 2 - Abacus, Bay / 2, ArchHeight, ArchDepth, ArchSegments)
    Sh_Turn_Y(From, <X0, Spring, ColumnZ(K) - Bay / 2>)
  #end
  #local Last = ColumnZ(0);
  #local H = ArchDepth / 2;
  #for (S, -1, 1, 2)
    Sh_Box(<X0 - H, Y0, -S * Last>, <X0 + H, Spring + ArchHeight, -S * (HalfZ - WallT)>)
  #end
#end

// A balustrade along x = X0 on the floor at Y0: in each bay a bottom rail, turned balusters
// and a hand rail.
#macro Balustrade(X0, Y0)
  #local K = 0; #local I = 0; // loop variables, local (see shapes.inc)
  #local Rail = 0.1;
  #local Height = 0.8;
  #local Spacing = 0.25;
  #local Profile = array[8] {
    <0.05, 0>,     <0.05, 0.06>,  <0.035, 0.1>,  <0.07, 0.3>,
    <0.045, 0.55>, <0.03, 0.68>,  <0.05, 0.74>,  <0.05, Height>
  }
  #for (K, 0, Columns - 2)
    #local Z0 = ColumnZ(K) - Abacus;
    #local Z1 = ColumnZ(K + 1) + Abacus;
    Sh_Box(<X0 - 0.12, Y0, Z0>, <X0 + 0.12, Y0 + Rail, Z1>)
    Sh_Box(<X0 - 0.14, Y0 + Rail + Height, Z0>, <X0 + 0.14, Y0 + 2 * Rail + Height, Z1>)
    #local Count = int((Z0 - Z1) / Spacing);
    #local Step = (Z0 - Z1) / Count;
    #for (I, 0, Count - 1)
      Sh_Lathe(<X0, Y0 + Rail, Z0 - Step * (I + 0.5)>, y, Profile, BalusterSegments)
    #end
  #end
#end

// ---- The courtyard, one mesh ----
Sh_Begin(60000, 70000)
Sh_Quad(<-HalfX, 0, HalfZ>, <0, 0, -2 * HalfZ>, <2 * HalfX, 0, 0>, 64, 24) // the paving
#for (S, -1, 1, 2)
  #local X0 = S * ArcadeX;
  Arcade(X0, 0, Ground, GroundArch)
  // The upper gallery's floor, which is the lower one's ceiling.
  #local Inner = S * (ArcadeX - ArchDepth / 2 - 0.1);
  #local Outer = S * (HalfX - WallT);
  Sh_Box(<Inner, Ground + GroundArch, -HalfZ + WallT>, <Outer, Floor2, HalfZ - WallT>)
  Balustrade(X0, Floor2)
  Arcade(X0, Floor2, Upper, UpperArch)
  // The galleries' roof and the outer wall.
  Sh_Box(<Inner, Top - Slab, -HalfZ + WallT>, <Outer, Top, HalfZ - WallT>)
  Sh_Box(<S * HalfX, 0, -HalfZ>, <Outer, Top, HalfZ>)
  // The end walls.
  Sh_Box(<-HalfX + WallT, 0, -S * HalfZ>, <HalfX - WallT, Top, -S * (HalfZ - WallT)>)
#end
Sh_Object(Stone)
