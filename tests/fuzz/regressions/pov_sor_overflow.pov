// A sor whose radius squared overflows single precision: an error at the count, not a shape
// of infinities.
sor { 4, <1e30, 0>, <1e30, 1>, <1e30, 2>, <1e30, 3> }
