// per-eye-view runs once: converting stereoshift's own output again changes nothing (the shader
// already carries the eye parameters), so the per-eye centre is never added twice.
// RUN: %stereoshift %s -o %t.once.frag
// RUN: %rmchecks %t.once.frag | FileCheck %s --check-prefix=ONCE
// RUN: %stereoshift %t.once.frag -o %t.twice.frag --report %t.json
// RUN: cmp %t.once.frag %t.twice.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Camera { vec3 cameraPosition; } camera;
layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inWorldPos;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 v = normalize(camera.cameraPosition - inWorldPos);
  outColor = texture(heightMap, inUV - v.xz * 0.02);
}
// ONCE: stereo.eyeOffsetX
// CHECK: "per-eye-view": {
// CHECK-NEXT: "result": "unchanged",
// CHECK-NEXT: "skipped": "the shader already carries stereo eye parameters ('eyeSign')"
