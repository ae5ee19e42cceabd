// Limits shared by the GLSL and the HLSL shaders of this example (both preprocessors read it).
#define MAX_LIGHTS 4
#define FOG_DENSITY 0.015
