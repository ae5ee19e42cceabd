// guarded-a.glsl and guarded-b.glsl include each other behind include guards: legal, it ends.
#ifndef GUARDED_A
#define GUARDED_A
#include "guarded-b.glsl"
float fromA(float v) { return v * 2.0; }
#endif
