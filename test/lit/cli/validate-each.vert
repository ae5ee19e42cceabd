// --validate-each validates the module after every pass that changed it (including the state
// after eye-params, where the block is declared but not used yet) and accepts a correct run
// without changing its output.
// RUN: %stereoshift --validate-each --verify %s -o %t.each.vert 2>&1 | FileCheck %s --allow-empty
// RUN: %stereoshift --verify %s -o %t.plain.vert
// RUN: cmp %t.each.vert %t.plain.vert
// RUN: %stereoshift %s --validate-each --verify --pass clip-position-detection --pass eye-params -o - | %rmchecks | FileCheck %s --check-prefix=DECLARED
// RUN: %stereoshift --validate-each --eye-source push-constant %S/Inputs/push-constant.vert -o - | %rmchecks | FileCheck %s --check-prefix=MERGED
// CHECK-NOT: error
// CHECK-NOT: invalid SPIR-V
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// DECLARED: uniform StereoParams
// MERGED: object.eyeSign * object.separation
