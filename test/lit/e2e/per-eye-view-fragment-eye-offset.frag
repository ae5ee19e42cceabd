// per-eye-view: with no matrix to derive the eye centre from, the fix adds the world-space eye
// offset to the eye parameters (eyeOffsetX/Y/Z at byte offsets 16, 20, 24 after a hudDepth slot)
// and the report says how the application fills them. The view vector here is `P - camera`
// (the other operand order) and the camera a neutral name: structure alone decides.
// RUN: %stereoshift --validate-each --verify %s -o %t.out.frag --report %t.json
// RUN: %rmchecks %t.out.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Frame { vec3 origin; float heightScale; } frame;
layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inWorldPos;
layout(location = 0) out vec4 outColor;
// CHECK: normalize(inWorldPos - stereoshift_eye_frame_origin(frame.origin))
// CHECK: layout(set = 0, binding = 2, std140) uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: float hudDepth;
// CHECK-NEXT: float eyeOffsetX;
// CHECK-NEXT: float eyeOffsetY;
// CHECK-NEXT: float eyeOffsetZ;
// CHECK-NEXT: } stereo;
void main() {
  vec3 toEye = normalize(inWorldPos - frame.origin);
// CHECK-NEXT: vec3 stereoshift_eye_frame_origin(vec3 stereoshift_camera)
// CHECK-NEXT: {
// CHECK-NEXT: return stereoshift_camera + vec3(stereo.eyeOffsetX, stereo.eyeOffsetY, stereo.eyeOffsetZ);
  float h = texture(heightMap, inUV).r;
  outColor = texture(heightMap, inUV + toEye.xz * h * frame.heightScale);
}
// REPORT: "per-eye-view": {
// REPORT-NEXT: "application": "fill eyeOffsetX/eyeOffsetY/eyeOffsetZ per eye with the world-space offset of the eye centre
// REPORT: "eye_centre": "frame.origin + vec3(eyeOffsetX, eyeOffsetY, eyeOffsetZ)  [no matrix to derive it from: set by the application]",
// REPORT: "why": "structure: a direction from it offsets texture coordinates in this stage"
// REPORT: "result": "changed"
