#pragma once
// Includes itself, but #pragma once makes the inner copy empty.
#include "once.glsl"
float fromOnce(float v) { return v - 1.0; }
