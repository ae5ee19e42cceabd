// --report writes a JSON report of what was done: the shader's file, stage, language (and how it
// was decided) and dialect, its classification, each pass's result and findings, the target, and
// whether it was emitted.
// RUN: rm -rf %t && mkdir %t
// RUN: %stereoshift --verify %s -o %t/out.vert --report %t/report.json
// RUN: FileCheck %s --input-file %t/report.json
// RUN: %python -m json.tool %t/report.json > /dev/null
// The report's directory is created when needed.
// RUN: %stereoshift %s -o %t/out2.vert --report %t/new/dir/report.json
// RUN: FileCheck %s --input-file %t/new/dir/report.json
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec4 vClip;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
  vClip = gl_Position;
}
// CHECK: {
// CHECK-NEXT: "changed": true,
// CHECK-NEXT: "classification": "perspective",
// CHECK-NEXT: "dialect": "450 vulkan",
// CHECK-NEXT: "file": "{{.*}}report.vert",
// CHECK-NEXT: "halo_copies": [
// CHECK-NEXT: "vClip"
// CHECK-NEXT: ],
// CHECK-NEXT: "language": "glsl",
// CHECK-NEXT: "language_reason": "#version directive",
// CHECK-NEXT: "language_source": "content",
// CHECK-NEXT: "ok": true,
// CHECK-NEXT: "output": "emitted",
// CHECK-NEXT: "output_file": "{{.*}}out{{2?}}.vert",
// CHECK-NEXT: "passes": {
// CHECK-NEXT: "clip-position-detection": {
// CHECK-NEXT: "classification": "perspective",
// CHECK-NEXT: "positions": [
// CHECK-NEXT: "gl_PerVertex.gl_Position"
// CHECK-NEXT: ],
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// CHECK-NEXT: "deferred-unprojection": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// CHECK-NEXT: "eye-params": {
// CHECK: "result": "changed",
// CHECK: "halo": {
// CHECK-NEXT: "result": "changed",
// CHECK-NEXT: "shifted_outputs": [
// CHECK-NEXT: "vClip"
// CHECK-NEXT: ]
// CHECK-NEXT: },
// CHECK-NEXT: "hud-at-depth": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// CHECK-NEXT: "per-eye-view": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// CHECK-NEXT: "stereo-shift": {
// CHECK-NEXT: "form": "branch",
// CHECK-NEXT: "result": "changed",
// CHECK-NEXT: "sites": 1
// CHECK-NEXT: }
// CHECK-NEXT: },
// CHECK-NEXT: "route": "glsl-source-splice",
// CHECK-NEXT: "stage": "vert",
// CHECK-NEXT: "stage_reason": "extension .vert",
// CHECK-NEXT: "target": "glsl",
// CHECK-NEXT: "timings_ms": {
