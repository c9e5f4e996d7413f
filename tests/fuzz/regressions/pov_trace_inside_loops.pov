// trace() and inside() in a loop over a changing object (each a new probe), on an unsupported
// object, with zero and enormous directions, from inside and from infinitely far: answers or
// errors at the position; never a crash or a hang.
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 10, -10> color rgb 1 }
#declare S = 0;
#for (I, 0, 200)
  #declare O = union { sphere { <I, 0, 0>, 1 } box { -1, 1 } blob { sphere { 0, 2, 1 } } }
  #declare N = <0, 0, 0>;
  #declare P = trace(O, <0, 10, 0>, -y, N) + trace(O, 0, <0, 0, 0>) + trace(O, 0, 1e30 * x, N);
  #declare S = S + inside(O, <I, 0, 0>) + inside(O, 1e30) + vlength(P);
#end
#declare U = height_field { png "missing.png" }
#declare V = trace(U, 0, y, N) + inside(U, 0);
sphere { 0, 1 }
