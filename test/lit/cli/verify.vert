// --verify recompiles the emitted shader with glslang and records it in the report; an emitted
// shader that does not compile (Vulkan GLSL asked for as GLSL 110, which has no uniform blocks)
// fails the run with the compiler's errors and writes no output, where without --verify it is written.
// RUN: %stereoshift --verify %s -o %t.ok.vert --report %t.json
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift %s -o %t.noverify.vert --report %t.noverify.json
// RUN: FileCheck %s --check-prefix=NOREPORT --input-file %t.noverify.json
// RUN: %not %stereoshift --verify --target glsl --target-version 110 %s -o %t.bad.vert 2>&1 | FileCheck %s --check-prefix=BAD
// RUN: test ! -e %t.bad.vert
// RUN: %stereoshift --target glsl --target-version 110 %s -o %t.unverified.vert
// RUN: %rmchecks %t.unverified.vert | FileCheck %s --check-prefix=UNVERIFIED
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// REPORT: "verified": true
// NOREPORT-NOT: "verified"
// BAD: (emitted){{.*}}: error:
// BAD: verify.vert: error: --verify: the emitted shader does not compile
// BAD: {{^[0-9]+}} errors generated.
// UNVERIFIED: #version 110
