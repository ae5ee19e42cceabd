// A tessellation-evaluation shader is the last pre-rasterization stage of a tessellation
// pipeline: its position gets the guarded shift at the end of main.
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s
#version 450
layout(triangles, equal_spacing, ccw) in;
// CHECK: #version 450
// CHECK: layout(triangles, ccw, equal_spacing) in;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
// CHECK: layout(set = 0, binding = 1, std140) uniform StereoParams
layout(location = 0) in vec3 inPos[];
layout(location = 0) out vec3 outNormal;
// CHECK-DAG: layout(location = 0) in vec3 inPos[];
// CHECK-DAG: layout(location = 0) out vec3 outNormal;
void main() {
  vec3 p = gl_TessCoord.x * inPos[0] + gl_TessCoord.y * inPos[1] + gl_TessCoord.z * inPos[2];
  outNormal = normalize(p);
  gl_Position = camera.viewProj * vec4(p, 1.0);
// CHECK: void main()
// CHECK: outNormal = normalize(p);
// CHECK: gl_Position =
// CHECK-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(gl_Position.w))))
// CHECK-NEXT: {
// CHECK-NEXT: precise float [[D:_[0-9]+]] = gl_Position.w - stereo.convergence;
// CHECK-NEXT: precise float [[S:_[0-9]+]] = stereo.eyeSign * stereo.separation;
// CHECK-NEXT: precise float [[O:_[0-9]+]] = [[S]] * [[D]];
// CHECK-NEXT: precise float [[X:_[0-9]+]] = gl_Position.x + [[O]];
// CHECK-NEXT: gl_Position.x = [[X]];
// CHECK-NEXT: }
// CHECK-NEXT: }
}
