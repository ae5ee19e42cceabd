// A Vulkan GLSL shader asked for a GLSL version Vulkan GLSL does not exist in (desktop 330) becomes
// OpenGL GLSL: the push-constant block turns into a plain uniform, descriptor sets go, and the
// output compiles as OpenGL GLSL 330 (it kept `push_constant` and `set =` before, which no OpenGL
// compiler takes).
// RUN: %stereoshift %s --target glsl --target-version 330 --verify -o %t.vert
// RUN: FileCheck %s < %t.vert
// RUN: %stereoshift %s --target essl --target-version 300 --verify -o %t.es.vert
// RUN: FileCheck %s --check-prefix=ES < %t.es.vert
// CHECK: #version 330
// CHECK-NOT: push_constant
// CHECK-NOT: set =
// CHECK: uniform Push pc;
// ES: #version 300 es
// ES-NOT: push_constant
#version 450
layout(push_constant) uniform Push { mat4 mvp; } pc;
layout(set = 0, binding = 0) uniform UBO { vec4 tint; } ubo;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outTint;
void main() {
  outTint = ubo.tint;
  gl_Position = pc.mvp * vec4(inPos, 1.0);
}
