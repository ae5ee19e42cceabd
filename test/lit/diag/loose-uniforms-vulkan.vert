// --eye-source=loose-uniforms on a Vulkan shader (Vulkan has no loose uniforms) is a clear error
// naming the option, like --eye-source=push-constant on an OpenGL shader, not an internal failure.
// RUN: %not %stereoshift --eye-source loose-uniforms %s -o %t.out 2>&1 | FileCheck %s
// CHECK-NOT: invalid SPIR-V
// CHECK: loose-uniforms-vulkan.vert: error: --eye-source=loose-uniforms
// CHECK-NOT: invalid SPIR-V
// CHECK: {{^}}1 error generated.
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
