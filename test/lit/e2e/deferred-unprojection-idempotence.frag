// Converting a converted deferred shader again changes nothing: the second run sees the eye
// parameters, leaves q alone (a second fix would subtract the parallax twice) and copies the file.
// RUN: %stereoshift --validate-each %s -o %t.once.frag
// RUN: %stereoshift --validate-each %t.once.frag --report %t.json -o %t.twice.frag
// RUN: cmp %t.once.frag %t.twice.frag
// RUN: FileCheck %s --input-file %t.json
// RUN: %rmchecks %t.once.frag | FileCheck %s --check-prefix=ONCE
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; } frame;
layout(set = 0, binding = 1) uniform sampler2D gDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {
  vec4 q = frame.invViewProj * vec4(inUV * 2.0 - 1.0, texture(gDepth, inUV).r, 1.0);
  outColor = vec4(q.xyz / q.w, 1.0);
}
// ONCE: frame.invViewProj[0] * ((stereo.eyeSign * stereo.separation)
// ONCE-NOT: frame.invViewProj[0]
// CHECK: "output": "copied",
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "left_alone": "the shader already carries stereo eye parameters ('eyeSign')",
// CHECK-NEXT: "result": "unchanged"
