// p.glsl and q.glsl include each other with no include guard.
#include "q.glsl"
float fromP(float v) { return v; }
