// `stereoshift verify` runs the original and the transpiled shader on lavapipe and checks the shift.
// RUN: %stereoshift verify %s | FileCheck %s
// RUN: %stereoshift verify --json --separation 0.1 --convergence 5 %s | FileCheck %s --check-prefix=JSON
// Without the halo pass the copied position stays mono: verify catches it and fails.
// RUN: %not %stereoshift verify --no-halo %s | FileCheck %s --check-prefix=HALO
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec4 outCopy;
layout(location = 1) out vec2 outUV;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
  outCopy = gl_Position;
  outUV = inPosition.xy;
}
// CHECK: verify.vert on {{.*}}: 96 vertices
// CHECK-NEXT: mono identity (eyeSign 0):   bit-exact
// CHECK-NEXT: other outputs per eye:       unchanged
// CHECK-NEXT: stereo x error:
// CHECK: {{^}}verified
// JSON-DAG: "mono_identical": true
// JSON-DAG: "other_outputs_unchanged": true
// JSON-DAG: "ok": true
// JSON-DAG: "vertices": 96
// HALO: problem: vertex {{[0-9]+}}: 'outCopy'.x (component 4), a copy of the position, was not shifted with it (halo)
// HALO: {{^}}FAILED
