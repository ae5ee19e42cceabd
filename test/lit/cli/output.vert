// -o FILE writes the converted shader there and nothing to stdout; `-o -` and no -o write stdout.
// RUN: rm -rf %t && mkdir %t
// RUN: %stereoshift %s -o %t/out.vert > %t/stdout.txt
// RUN: %rmchecks %t/out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=EMPTY --allow-empty --input-file %t/stdout.txt
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift %s | %rmchecks | FileCheck %s
// RUN: %stereoshift %s --output=%t/long.vert
// RUN: cmp %t/out.vert %t/long.vert
// Writing into a directory that does not exist yet creates it.
// RUN: %stereoshift %s -o %t/new/dir/out.vert
// RUN: cmp %t/out.vert %t/new/dir/out.vert
// EMPTY-NOT: {{.}}
#version 450
// CHECK: #version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
// CHECK: uniform StereoParams
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: stereo.eyeSign * stereo.separation
