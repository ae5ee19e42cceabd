layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
