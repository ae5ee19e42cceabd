// Without --gl-binding the injected OpenGL uniform block has no binding (bound by name), and the
// loose uniforms of the source gain none either.
// RUN: %stereoshift --verify --eye-source uniform-block %s -o - | %rmchecks | FileCheck %s
#version 450
uniform mat4 uMVP;
layout(location = 0) in vec3 aPosition;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
// CHECK: {{^}}#version 450
// CHECK-NOT: binding
// CHECK: {{^}}uniform mat4 uMVP;
// CHECK-NOT: binding
// CHECK: {{^}}layout(std140) uniform StereoParams
// CHECK-NOT: binding
