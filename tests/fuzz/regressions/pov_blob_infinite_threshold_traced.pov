// Found by the POV fuzzer: an infinite blob threshold (0.1e3086) passed the reader, and
// trace() prepared the object, whose error then named no place.
#declare Mound = blob { threshold 0.1e3086 sphere { 0, 1, 1 } }
#declare V = trace(Mound, <0, 5, 0>, -y);
