// deferred-unprojection, view-space form: an inverse projection rebuilds the view-space position
// (SSAO / light culling style). Same fix with the inverse projection's column 0; the report names
// the form from the matrix name. The depth is read through a helper function and the NDC is built
// in another, so the data flow is followed through calls, parameters and return values.
// RUN: %stereoshift --validate-each --verify %s --report %t.json -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 invProj; } camera;
layout(set = 0, binding = 1) uniform sampler2D sceneDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outViewPos;
float sampleDepth(vec2 uv) { return texture(sceneDepth, uv).r; }
vec2 toNdc(vec2 uv) { return uv * 2.0 - 1.0; }
void main() {
  vec4 q = camera.invProj * vec4(toNdc(inUV), sampleDepth(inUV), 1.0);
  outViewPos = vec4(q.xyz / q.w, 1.0);
}
// CHECK: vec4 q = stereoshift_unproject_camera_invProj(camera.invProj * vec4(toNdc(inUV), sampleDepth(inUV), 1.0));
// CHECK: return stereo.eyeSign != 0.0 ? stereoshift_q - camera.invProj[0] * ((stereo.eyeSign * stereo.separation) * (1.0 - stereo.convergence * stereoshift_q.w)) : stereoshift_q;

// REPORT: "depth": "sceneDepth",
// REPORT-NEXT: "depth_range": "as sampled ([0, 1])",
// REPORT: "form": "view-space position from an inverse projection",
// REPORT-NEXT: "matrix": "camera.invProj",
// REPORT-NEXT: "ndc": "inUV"
