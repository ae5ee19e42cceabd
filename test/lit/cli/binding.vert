// --binding sets the injected block's binding (default: one past the highest used in its set).
// RUN: %stereoshift --verify --binding 7 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify --set 2 --binding 4 %s -o - | %rmchecks | FileCheck %s --check-prefix=SET2
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(set = 0, binding = 3) uniform Object { mat4 model; } object;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * object.model * vec4(inPosition, 1.0);
}
// CHECK: layout(set = 0, binding = 7, std140) uniform StereoParams
// SET2: layout(set = 2, binding = 4, std140) uniform StereoParams
// DEFAULT: layout(set = 0, binding = 4, std140) uniform StereoParams
