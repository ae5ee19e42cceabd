// A tessellation-evaluation shader is the last pre-rasterization stage of a tessellation
// pipeline: its position gets the guarded shift at the end of main (the spliced text: main
// renamed, the layouts as written, the shifting main appended).
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s
// CHECK: #version 450
// CHECK-NEXT: layout(triangles, equal_spacing, ccw) in;
// CHECK: layout(location = 0) in vec3 inPos[];
// CHECK-NEXT: layout(location = 0) out vec3 outNormal;
// CHECK-NEXT: void main_stereoshift_mono() {
// CHECK: outNormal = normalize(p);
// CHECK-NEXT: gl_Position = camera.viewProj * vec4(p, 1.0);
// CHECK: layout(set = 0, binding = 1, std140) uniform StereoParams
// CHECK: void main()
// CHECK-NEXT: {
// CHECK-NEXT: main_stereoshift_mono();
// CHECK-NEXT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NEXT: {
// CHECK-NEXT: precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
// CHECK-NEXT: gl_Position.x = stereoshift_x;
// CHECK-NEXT: }
// CHECK-NEXT: }
#version 450
layout(triangles, equal_spacing, ccw) in;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPos[];
layout(location = 0) out vec3 outNormal;
void main() {
  vec3 p = gl_TessCoord.x * inPos[0] + gl_TessCoord.y * inPos[1] + gl_TessCoord.z * inPos[2];
  outNormal = normalize(p);
  gl_Position = camera.viewProj * vec4(p, 1.0);
}
