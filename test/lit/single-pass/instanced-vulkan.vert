// --eye-source instanced, Vulkan GLSL (an instanced-drawing sample reading per-instance data by
// gl_InstanceIndex): the application doubles the instance count; the eye is the low bit of the
// instance index, written to gl_Layer (GL_ARB_shader_viewport_layer_array) and to the flat
// varying stereoEye; every other read of gl_InstanceIndex becomes the original instance, >> 1.
// Converting the output again is a no-op.
// The single-pass modes are not spliced into the source text: SPIRV-Cross re-emits, with a note.
// RUN: %stereoshift --eye-source instanced --validate-each --verify %s -o %t.1.vert --report %t.json 2>%t.notes
// RUN: FileCheck %s --check-prefix=NOTE --input-file %t.notes
// NOTE: instanced-vulkan.vert: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the single-pass stereo modes other than Vulkan multiview are written by SPIRV-Cross
// RUN: %rmchecks %t.1.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift --eye-source instanced %t.1.vert -o %t.2.vert
// RUN: cmp %t.1.vert %t.2.vert
// RUN: %stereoshift --eye-source instanced --eye-route viewport %s -o - | FileCheck %s --check-prefix=VIEWPORT
#version 450
layout(location = 0) in vec3 inPos;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } cam;
layout(set = 0, binding = 1) readonly buffer Instances { vec4 offsets[]; } instances;
layout(location = 0) out vec3 vColor;
void main() {
    vec4 offset = instances.offsets[gl_InstanceIndex];
    gl_Position = cam.viewProj * vec4(inPos + offset.xyz, 1.0);
    vColor = vec3(float(gl_InstanceIndex) * 0.1);
}
// CHECK: #extension GL_ARB_shader_viewport_layer_array : require
// CHECK: layout(location = 15) flat out int stereoEye;
// CHECK: int [[EYE:_[0-9]+]] = gl_InstanceIndex & 1;
// CHECK-NEXT: gl_Layer = [[EYE]];
// CHECK-NEXT: stereoEye = [[EYE]];
// CHECK-NEXT: vec4 offset = instances.offsets[gl_InstanceIndex >> 1];
// CHECK: vColor = vec3(float(gl_InstanceIndex >> 1)
// CHECK: precise float {{.*}} = (((gl_InstanceIndex & 1) != 0) ? 1.0 : (-1.0)) * stereo.separation;
// REPORT: "single-pass-stereo": {
// REPORT-NEXT: "eye_varying": {
// REPORT-NEXT: "location": 15,
// REPORT-NEXT: "name": "stereoEye"
// REPORT-NEXT: },
// REPORT-NEXT: "eye_written_to": "layer",
// REPORT-NEXT: "instance_reads_rewritten": 2,
// VIEWPORT: gl_ViewportIndex = [[EYE:_[0-9]+]];
