// --eye-source multiview, Vulkan GLSL: eyeSign is the view index (view 0 the left eye, -1), the
// rest of the shift as in two passes; separation and convergence stay in the StereoParams block.
// Converting the output again is a no-op (it reads the view index: already stereo).
// Spliced into the source text (gl_ViewIndex's eye sign, GL_EXT_multiview required after #version);
// with an explicit --target-version SPIRV-Cross re-emits the IR's same shift.
// RUN: %stereoshift --eye-source multiview --validate-each --verify %s -o %t.1.vert --report %t.json 2>%t.notes
// RUN: FileCheck %s --check-prefix=NOTE --allow-empty --input-file %t.notes
// NOTE-NOT: re-emitted
// RUN: %stereoshift --eye-source multiview --target-version 450 %s -o - | %rmchecks | FileCheck %s --check-prefix=REEMIT
// RUN: %rmchecks %t.1.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift --eye-source multiview %t.1.vert -o %t.2.vert 2>&1 | FileCheck %s --check-prefix=AGAIN
// RUN: cmp %t.1.vert %t.2.vert
// RUN: %stereoshift --eye-source multiview --swap-eyes %s -o - | FileCheck %s --check-prefix=SWAP
#version 450
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inTexCoord;
layout(binding = 0) uniform UniformBufferObject {
    mat4 model;
    mat4 view;
    mat4 proj;
} ubo;
layout(location = 0) out vec2 fragTexCoord;
void main() {
    gl_Position = ubo.proj * ubo.view * ubo.model * vec4(inPosition, 1.0);
    fragTexCoord = inTexCoord;
}
// CHECK: #extension GL_EXT_multiview : require
// CHECK: uniform StereoParams
// CHECK: float separation;
// CHECK: precise float stereoshift_x = gl_Position.x + ((gl_ViewIndex != 0 ? 1.0 : -1.0) * stereo.separation) * (gl_Position.w - stereo.convergence);
// CHECK-NOT: stereo.eyeSign
// REEMIT: #extension GL_EXT_multiview : require
// REEMIT: precise float {{.*}} = ((gl_ViewIndex != 0) ? 1.0 : (-1.0)) * stereo.separation;
// REEMIT-NOT: stereo.eyeSign
// REPORT: "single-pass-stereo": {
// REPORT-NEXT: "mode": "multiview",
// REPORT-NEXT: "result": "changed"
// AGAIN: note: shader already carries stereo eye parameters
// SWAP: ((gl_ViewIndex != 0 ? -1.0 : 1.0) * stereo.separation)
