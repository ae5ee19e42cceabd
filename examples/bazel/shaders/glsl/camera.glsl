// The camera block every GLSL scene shader uses.
layout(set = 0, binding = 0) uniform Camera {
    mat4 viewProjection;
    vec4 eyePosition;
} camera;
