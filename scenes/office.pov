// The built-in scene "office" (core/scenes/builtin_office.cpp) in POV-Ray's language: a
// furnished room of 36,308 triangles in 147 mesh objects (15 workplaces of desk, chair,
// monitor, keyboard and desk lamp; 8 bookcases with rows of books; plants), diffuse materials
// lit by two pendant lights.
//
//   render scenes/office.pov -W 640 -H 480 -o office.png      (the same picture as builtin:office)
//   povray +Iscenes/office.pov +W640 +H480 -D +Ooffice.png
//
// Coordinates are the C++ scene's with z negated (POV-Ray is left-handed; see shapes.inc), so
// the bookcases stand on the wall at z = +7 and the camera looks from z = -6.3.
#version 3.7;
#include "shapes.inc"

global_settings { assumed_gamma 1.0 }

// The room spans x in [-RoomX, RoomX], y in [0, RoomY], z in [-RoomZ, RoomZ].
#declare RoomX = 10;
#declare RoomY = 3.2;
#declare RoomZ = 7;

camera {
  perspective
  location <-9.2, 1.8, -6.3>
  up y
  right x * image_width / image_height
  direction z * 0.5 / tan(radians(55 / 2)) // a 55 degree vertical field of view
  look_at <1.5, 0.7, 3>
}
background { rgb 0 }

// ---- Materials: all diffuse, with a little Phong highlight ----
#macro Diffuse(Color, Phong)
  texture {
    pigment { rgb Color }
    finish { ambient 0.1 diffuse 0.7 phong Phong phong_size 30 }
  }
#end
#declare Wood    = Diffuse(<0.6, 0.42, 0.25>, 0.15)
#declare Metal   = Diffuse(<0.55, 0.57, 0.6>, 0.4)
#declare Fabric  = Diffuse(<0.2, 0.3, 0.55>, 0.02)
#declare Plastic = Diffuse(<0.15, 0.15, 0.17>, 0.25)
#declare Screen  = Diffuse(<0.05, 0.08, 0.12>, 0.5)
#declare Wall    = Diffuse(<0.85, 0.82, 0.75>, 0)
#declare Floor   = Diffuse(<0.45, 0.4, 0.36>, 0.05)
#declare Ceiling = Diffuse(<0.92, 0.92, 0.9>, 0)
#declare Shade   = Diffuse(<0.8, 0.15, 0.1>, 0.3)
#declare Bulb    = Diffuse(<1, 0.97, 0.85>, 0.2)
#declare Pot     = Diffuse(<0.6, 0.3, 0.18>, 0.1)
#declare Leaf    = Diffuse(<0.2, 0.55, 0.2>, 0.05)
// The books: one colour per shelf (POV-Ray takes no macro calls in an array initialiser).
#declare Book_Colors = array[6] {
  <0.6, 0.1, 0.1>, <0.1, 0.3, 0.6>, <0.15, 0.5, 0.2>, <0.8, 0.7, 0.3>, <0.4, 0.2, 0.5>, <0.85, 0.85, 0.8>
}
#declare Books = array[6];
#for (I, 0, 5)
  #declare Books[I] = Diffuse(Book_Colors[I], 0.1)
#end

// The built-in scene's random numbers: a 32-bit linear congruential generator with a fixed
// seed (exact in POV-Ray's double-precision floats), so the books come out the same.
#declare Lcg_State = 12345;
#macro Lcg_Range(Lo, Hi)
  #declare Lcg_State = mod(Lcg_State * 1664525 + 1013904223, 4294967296);
  (Lo + (Hi - Lo) * floor(Lcg_State / 256) / 16777216)
#end

// ---- The room: floor, ceiling and walls facing inwards, whiteboard, door, ceiling panels ----
#macro Room(TilesX, TilesZ)
  #local I = 0; // loop variables, local (see shapes.inc)
  #local W = 2 * RoomX;
  #local D = 2 * RoomZ;
  Sh_Reset() Sh_Quad(<-RoomX, 0, RoomZ>, <0, 0, -D>, <W, 0, 0>, TilesZ, TilesX) Sh_Object(Floor)
  Sh_Reset() Sh_Quad(<-RoomX, RoomY, RoomZ>, <W, 0, 0>, <0, 0, -D>, 4, 4) Sh_Object(Ceiling)
  Sh_Reset() Sh_Quad(<-RoomX, 0, RoomZ>, <0, RoomY, 0>, <0, 0, -D>, 2, 4) Sh_Object(Wall) // west
  Sh_Reset() Sh_Quad(<RoomX, 0, RoomZ>, <0, 0, -D>, <0, RoomY, 0>, 4, 2) Sh_Object(Wall)  // east
  Sh_Reset() Sh_Quad(<-RoomX, 0, RoomZ>, <W, 0, 0>, <0, RoomY, 0>, 4, 2) Sh_Object(Wall)  // far
  Sh_Reset() Sh_Quad(<-RoomX, 0, -RoomZ>, <0, RoomY, 0>, <W, 0, 0>, 2, 4) Sh_Object(Wall) // near
  Sh_Reset() Sh_Box(<-RoomX, 1, 2>, <-RoomX + 0.04, 2.2, -1.5>) Sh_Object(Ceiling) // whiteboard
  Sh_Reset() Sh_Box(<RoomX - 0.05, 0, -2.5>, <RoomX, 2.1, -3.5>) Sh_Object(Wood)   // door
  #for (I, 0, 3) // light panels in the ceiling
    #local X = -6 + 4 * I;
    Sh_Reset() Sh_Box(<X - 0.6, RoomY - 0.03, -3.5>, <X + 0.6, RoomY, -4.1>) Sh_Object(Bulb)
  #end
#end

// ---- A workplace whose desk is centred at (X, Z); its user sits on the -z side ----
#macro Workplace(X, Z)
  #local SX = 0; #local SZ = 0; // loop variables, local (see shapes.inc)
  #local Top = 0.74;
  #local HW = 0.7;
  #local HD = 0.4;
  // The desk: top, four legs, a modesty panel at the back.
  Sh_Reset()
  Sh_Box(<X - HW, Top - 0.04, Z + HD>, <X + HW, Top, Z - HD>)
  #for (SX, -1, 1, 2)
    #for (SZ, -1, 1, 2)
      #local LX = X + SX * (HW - 0.05);
      #local LZ = Z - SZ * (HD - 0.05);
      Sh_Box(<LX - 0.03, 0, LZ + 0.03>, <LX + 0.03, Top - 0.04, LZ - 0.03>)
    #end
  #end
  Sh_Box(<X - HW + 0.05, 0.3, Z + HD - 0.03>, <X + HW - 0.05, Top - 0.04, Z + HD - 0.05>)
  Sh_Object(Wood)

  // The chair: seat, back, two back posts and four round legs.
  #local CZ = Z - HD - 0.35;
  #local Seat = 0.45;
  Sh_Reset()
  Sh_Box(<X - 0.22, Seat - 0.04, CZ + 0.22>, <X + 0.22, Seat, CZ - 0.22>)
  Sh_Box(<X - 0.22, Seat + 0.15, CZ - 0.2>, <X + 0.22, Seat + 0.5, CZ - 0.23>)
  #for (SX, -1, 1, 2)
    Sh_Box(<X + SX * 0.18 - 0.015, Seat, CZ - 0.2>, <X + SX * 0.18 + 0.015, Seat + 0.15, CZ - 0.23>)
    #for (SZ, -1, 1, 2)
      #local Foot = <X + SX * 0.19, 0, CZ - SZ * 0.19>;
      Sh_Cylinder(Foot, Foot + <0, Seat - 0.04, 0>, 0.018, 16, true)
    #end
  #end
  Sh_Object(Fabric)

  // The monitor: a screen on a round stand and foot.
  #local MBase = <X, Top, Z + 0.22>;
  Sh_Reset()
  Sh_Cylinder(MBase, MBase + <0, 0.012, 0>, 0.11, 24, true)
  Sh_Cylinder(MBase, MBase + <0, 0.2, 0>, 0.02, 16, true)
  Sh_Box(<X - 0.27, Top + 0.16, Z + 0.215>, <X + 0.27, Top + 0.48, Z + 0.185>)
  Sh_Object(Screen)

  Sh_Reset()
  Sh_Box(<X - 0.22, Top, Z - 0.02>, <X + 0.22, Top + 0.02, Z - 0.17>)
  Sh_Object(Plastic) // the keyboard

  // The desk lamp: a round foot, two arms with a joint, a conical shade and a bulb.
  #local LB = <X + HW - 0.15, Top, Z + HD - 0.15>;
  #local Joint = LB + <-0.05, 0.32, -0.05>;
  #local Head = Joint + <-0.2, 0.08, -0.1>;
  Sh_Reset()
  Sh_Cylinder(LB, LB + <0, 0.02, 0>, 0.08, 32, true)
  Sh_Cylinder(LB, Joint, 0.01, 16, true)
  Sh_Sphere(Joint, 0.018, 8, 12)
  Sh_Cylinder(Joint, Head, 0.01, 16, true)
  Sh_Cone(Head + <0, -0.13, 0>, Head, 0.08, 0.03, 32, false)
  Sh_Sphere(Head + <0, -0.08, 0>, 0.025, 8, 12)
  Sh_Object(Metal)
#end

// ---- A bookcase on the far wall with its left side at X, and a row of books per shelf ----
#macro Bookcase(Id, X)
  #local S = 0; // loop variables, local (see shapes.inc)
  #local W = 1.6;
  #local H = 2;
  #local D = 0.35;
  #local T = 0.025;
  #local Z0 = RoomZ;     // against the wall
  #local Z1 = RoomZ - D; // the front
  #local Shelves = 5;
  Sh_Reset()
  Sh_Box(<X, 0, Z0>, <X + T, H, Z1>)
  Sh_Box(<X + W - T, 0, Z0>, <X + W, H, Z1>)
  Sh_Box(<X + T, 0, Z0>, <X + W - T, H, Z0 - T>) // the back panel
  #for (S, 0, Shelves)
    #local Y = (S = Shelves ? H - T : S * H / Shelves);
    Sh_Box(<X + T, Y, Z0 - T>, <X + W - T, Y + T, Z1>)
  #end
  Sh_Object(Wood)
  // Books of random width, height and depth, side by side until the shelf is full.
  #for (S, 0, Shelves - 1)
    #local Y = S * H / Shelves + T;
    #local BX = X + T + 0.01;
    Sh_Reset()
    #local Full = false;
    #while (!Full)
      #local BW = Lcg_Range(0.035, 0.075);
      #local BH = Lcg_Range(0.2, 0.34);
      #local BD = Lcg_Range(0.2, 0.3);
      #if (BX + BW > X + W - T - 0.01)
        #local Full = true;
      #else
        Sh_Box(<BX, Y, Z0 - T>, <BX + BW, Y + BH, Z0 - T - BD>)
        #local BX = BX + BW + 0.002;
      #end
    #end
    Sh_Object(Books[mod(Id + S, 6)])
  #end
#end

// ---- A potted plant standing at At: a conical pot and three balls of leaves ----
#macro Plant(At)
  Sh_Reset() Sh_Cone(At, At + <0, 0.45, 0>, 0.16, 0.22, 24, true) Sh_Object(Pot)
  Sh_Reset()
  Sh_Sphere(At + <0, 0.8, 0>, 0.35, 10, 14)
  Sh_Sphere(At + <0.15, 1.05, -0.05>, 0.25, 8, 12)
  Sh_Sphere(At + <-0.1, 1.1, 0.1>, 0.22, 8, 12)
  Sh_Object(Leaf)
#end

// ---- A pendant lamp: a rod and a conical shade from the ceiling, a bulb, and the light at
// At, just below the shade ----
#macro Pendant(At)
  #local Rod = <At.x, RoomY - 0.4, At.z>;
  Sh_Reset()
  Sh_Cylinder(Rod, <At.x, RoomY, At.z>, 0.01, 16, true)
  Sh_Cone(At + <0, 0.1, 0>, Rod, 0.4, 0.1, 48, false)
  Sh_Object(Shade)
  Sh_Reset() Sh_Sphere(At + <0, 0.22, 0>, 0.07, 10, 16) Sh_Object(Bulb)
  light_source { At color rgb 0.6 }
#end

// ---- The scene ----
Sh_Begin(2000, 3000)
Room(22, 15) // floor tiles, chosen so that the total is the paper's 36,308 triangles
#for (Row, 0, 2)
  #for (Column, 0, 4)
    Workplace(-7 + 3.5 * Column, 3.2 - 2.8 * Row)
  #end
#end
#for (I, 0, 7)
  Bookcase(I, -9.6 + 1.65 * I)
#end
Plant(<-9.4, 0, 5.8>)
Plant(<9.4, 0, 6.4>)
Plant(<9.3, 0, -6.3>)
Plant(<9.3, 0, -0.5>)
Pendant(<-3.5, RoomY - 0.75, -0.6>)
Pendant(<3.5, RoomY - 0.75, 1.2>)
