// --eye-source=push-constant on an OpenGL shader (push constants are Vulkan only) is a clear error.
// RUN: %not %stereoshift --eye-source push-constant %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: push-constant-opengl.vert: error: --eye-source=push-constant needs a Vulkan shader; this is OpenGL GLSL
// CHECK-NEXT: {{^}}1 error generated.
#version 330
uniform mat4 uMVP;
in vec3 aPosition;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
