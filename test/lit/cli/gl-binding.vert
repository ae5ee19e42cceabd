// --gl-binding gives the injected OpenGL uniform block an explicit binding (GLSL 420+), instead of
// leaving it to be bound by name.
// RUN: %stereoshift --verify --eye-source uniform-block --gl-binding 3 %s -o - | %rmchecks | FileCheck %s
#version 450
uniform mat4 uMVP;
layout(location = 0) in vec3 aPosition;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
// CHECK: layout(binding = 3, std140) uniform StereoParams
