// per-eye-view: a parallax-occlusion fragment shader that builds its view vector per pixel from the
// camera position (a vec4 block member, used as .xyz) gets the per-eye centre
// C + InvVP * (e*S*C, 0, 0, 0), with the inverse view-projection its camera block already carries.
// Decided by structure: a normalized direction from the camera offsets the texture coordinates.
// RUN: %stereoshift --validate-each --verify %s -o %t.out.frag --report %t.json
// RUN: %rmchecks %t.out.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Camera {
  mat4 viewProj;
  mat4 invViewProj;
  vec4 position;
} camera;
layout(set = 1, binding = 0) uniform sampler2D heightMap;
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inWorldPos;
layout(location = 2) in mat3 inWorldToTangent;
layout(location = 0) out vec4 outColor;
// CHECK: vec3 v = normalize(inWorldToTangent * (stereoshift_eye_camera_position(camera.position).xyz - inWorldPos));
// CHECK: uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } stereo;
void main() {
  vec3 v = normalize(inWorldToTangent * (camera.position.xyz - inWorldPos));
// CHECK-NEXT: vec4 stereoshift_eye_camera_position(vec4 stereoshift_camera)
// CHECK-NEXT: {
// CHECK-NEXT: return stereoshift_camera + vec4((camera.invViewProj * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
  vec2 step = -v.xy / max(v.z, 0.05) * 0.04 / 16.0;
  vec2 uv = inUV;
  for (int i = 0; i < 16 && texture(heightMap, uv).r < 1.0 - float(i) / 16.0; ++i)
    uv += step;
  outColor = texture(heightMap, uv);
}
// REPORT: "per-eye-view": {
// REPORT-NEXT: "fixed": [
// REPORT-NEXT: {
// REPORT-NEXT: "eye_centre": "camera.position + (camera.invViewProj * vec4(eyeSign*separation*convergence, 0, 0, 0)).xyz  [inverse view-projection by name]",
// REPORT-NEXT: "loads_replaced": 1,
// REPORT-NEXT: "uniform": "camera.position",
// REPORT-NEXT: "why": "structure: a direction from it offsets texture coordinates in this stage (the name agrees)"
// REPORT: "per_eye_outputs": [
// REPORT-NEXT: "outColor"
// REPORT: "result": "changed"
