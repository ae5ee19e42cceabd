// Includes itself with no include guard: the include never ends.
float helper(float v) { return v; }
#include "x.hlsli"
