// --camera-uniform with a name the shader does not read: a warning, and nothing else changes.
// RUN: %stereoshift --camera-uniform uNoSuchCamera %s -o %t.out.vert 2>&1 | FileCheck %s
// CHECK: warning: --camera-uniform 'uNoSuchCamera': no vec3/vec4 uniform of that name is read in this shader
#version 450
layout(set = 0, binding = 0) uniform Globals { mat4 viewProj; } g;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = g.viewProj * vec4(inPosition, 1.0);
}
