// guarded-b.glsl and guarded-a.glsl include each other behind include guards: legal, it ends.
#ifndef GUARDED_B
#define GUARDED_B
#include "guarded-a.glsl"
float fromB(float v) { return v + 1.0; }
#endif
