// --camera-uniform NAME forces a uniform with a name no hint recognises (and a use structure alone
// cannot decide in a vertex shader alone) to be the camera: every load becomes the per-eye centre.
// Without the option the shader only gets the shift; with it, the camera's reads also go through a
// helper that adds this eye's offset. Both spliced into the shader's own text.
// RUN: %stereoshift --camera-uniform uP0 --validate-each --verify %s -o %t.out.vert --report %t.json
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift %s -o %t.plain.vert
// RUN: %rmchecks %t.plain.vert | FileCheck %s --check-prefix=PLAIN
#version 450
layout(set = 0, binding = 0) uniform Globals { mat4 uVP; vec3 uP0; } g;
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 outRay;
void main() {
  outRay = inPosition - g.uP0;
// CHECK: outRay = inPosition - stereoshift_eye_g_uP0(g.uP0);
// CHECK: return stereoshift_camera + (inverse(g.uVP) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz;
// PLAIN: outRay = inPosition - g.uP0;
// PLAIN-NOT: inverse(
// PLAIN: main_stereoshift_mono();
// PLAIN-NEXT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
  gl_Position = g.uVP * vec4(inPosition, 1.0);
}
// REPORT-NOT: re-emitted
// REPORT: "uniform": "g.uP0",
// REPORT-NEXT: "why": "forced by --camera-uniform"
// REPORT: "result": "changed"
// REPORT: "route": "glsl-source-splice"
