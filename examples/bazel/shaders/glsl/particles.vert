#version 450
layout(location = 0) in vec4 inPositionAndSize;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProjection; } camera;

void main() {
    gl_PointSize = inPositionAndSize.w;
    gl_Position = camera.viewProjection * vec4(inPositionAndSize.xyz, 1.0);
}
