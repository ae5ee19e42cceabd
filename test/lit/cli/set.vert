// --set puts the injected block in another descriptor set; its default binding is then the first
// one of that set (0), since the shader uses nothing in set 3.
// RUN: %stereoshift --verify --set 3 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify --set 0 %s -o - | %rmchecks | FileCheck %s --check-prefix=SET0
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec3 inPosition;
void main() {
  float h = textureLod(heightMap, inPosition.xz, 0.0).r;
  gl_Position = camera.viewProj * vec4(inPosition + vec3(0.0, h, 0.0), 1.0);
}
// CHECK: layout(set = 0, binding = 0) uniform Camera
// CHECK: layout(set = 3, binding = 0, std140) uniform StereoParams
// SET0: layout(set = 0, binding = 2, std140) uniform StereoParams
