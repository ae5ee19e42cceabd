// --pass is "repeatable" (one name per flag), so the input file after it is the input, not one
// more pass name: `stereoshift --pass NAME shader.vert` works like `stereoshift shader.vert --pass NAME`.
// RUN: %stereoshift --pass clip-position-detection --pass eye-params %s -o - | %rmchecks | FileCheck %s
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: uniform StereoParams
