// An application block already called StereoParams (instance `stereo`): the injected block and
// instance are renamed, the rename is reported, and the shift reads the injected block.
// RUN: %stereoshift --verify %s -o %t.out.vert 2>&1 | FileCheck %s --check-prefix=WARN
// RUN: %rmchecks %t.out.vert | FileCheck %s
// WARN: warning: the shader already declares 'StereoParams'
#version 450
layout(set = 0, binding = 0) uniform StereoParams { mat4 viewProj; } stereo;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = stereo.viewProj * vec4(inPosition, 1.0);
}
// CHECK: layout(set = 0, binding = 0) uniform StereoParams { mat4 viewProj; } stereo;
// CHECK: uniform [[BLOCK:StereoParams[_0-9a-z]+]]
// CHECK: } [[INST:stereo[_0-9a-z]+]];
// CHECK: [[INST]].eyeSign * [[INST]].separation
