// Two nested loops of 999,999 runs each, with a body of one assignment: 10^12 runs in all,
// stopped by the loops' budget (loop_iterations, all loops together) in about a second; the
// parse-step budget alone took 8.3 s.
#declare I = 0;
#while (I < 999999)
  #declare J = 0;
  #while (J < 999999)
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
