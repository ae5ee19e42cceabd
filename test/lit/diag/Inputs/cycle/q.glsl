// q.glsl and p.glsl include each other with no include guard.
#include "p.glsl"
float fromQ(float v) { return v; }
