// An OpenGL shader (a loose uniform) with a real error: the message names that error (a double
// vertex input needs GLSL 410), not the Vulkan rules' complaint about the loose uniform, which
// is no error in OpenGL GLSL.
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// CHECK-NOT: Vulkan
// CHECK: opengl-style-real-error.vert:[[@LINE+5]]:1: error: 'vertex-shader `double` type input' : not supported for this version or the enabled extensions
// CHECK-NOT: Vulkan
// CHECK: {{^}}1 error generated.
#version 400
uniform mat4 mvp;
in dvec4 position;
void main() { gl_Position = mvp * vec4(position); }
