// A shader that needs no change (clip w is the literal 1.0) is copied byte for byte; with
// --force-reemit it goes through the back end anyway (and still gets no eye parameters).
// RUN: %stereoshift --verify %s -o %t.copy.vert --report %t.copy.json
// RUN: cmp %s %t.copy.vert
// RUN: FileCheck %s --check-prefix=COPY --input-file %t.copy.json
// RUN: %stereoshift --verify --force-reemit %s -o %t.emit.vert --report %t.emit.json
// RUN: %rmchecks %t.emit.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=EMIT --input-file %t.emit.json
#version 450
layout(location = 0) in vec2 inPosition;
void main() {
  gl_Position = vec4(inPosition, 0.0, 1.0);
}
// CHECK: #version 450
// CHECK-NOT: {{R}}UN:
// CHECK-NOT: StereoParams
// CHECK: void main()
// CHECK-NEXT: {
// CHECK-NEXT: gl_Position = vec4(inPosition, 0.0, 1.0);
// CHECK-NEXT: }
// COPY: "classification": "2d-constant-w",
// COPY: "output": "copied",
// EMIT: "classification": "2d-constant-w",
// EMIT: "output": "emitted",
