#version 300 es
// An OpenGL ES multiview shader (GL_OVR_multiview2) is stereo already: copied unchanged. Re-emitted
// anyway (another ESSL version), the output declares `layout(num_views = 2) in;` again, which SPIR-V
// does not carry (SPIRV-Cross refuses an OpenGL multiview shader without the count).
// RUN: %stereoshift %s -o %t.vert 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: cmp %s %t.vert
// RUN: %stereoshift %s --target essl --target-version 310 --verify -o - 2>/dev/null | FileCheck %s --check-prefix=EMIT
// NOTE: already-stereo-ovr.vert: note: shader reads the view index {{.*}} never shifted twice
// EMIT: #extension GL_OVR_multiview2 : require
// EMIT: layout(num_views = 2) in;
// EMIT-NOT: eyeSign
#extension GL_OVR_multiview2 : require
layout(num_views = 2) in;
uniform mat4 u_viewProjection[2];
uniform mat4 u_model;
in vec3 a_position;
void main() {
  gl_Position = u_viewProjection[gl_ViewID_OVR] * u_model * vec4(a_position, 1.0);
}
