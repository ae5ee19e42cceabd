#version 330
// --diff prints the conversion's edits as a unified diff against the input instead of the output
// text; the diff applies with `patch` and gives the very output a plain run writes.
// RUN: %stereoshift --diff %s -o - > %t.patch
// RUN: %rmchecks %t.patch | FileCheck %s
// RUN: cp %s %t.vert
// RUN: patch -s %t.vert %t.patch
// RUN: %stereoshift %s -o %t.expected.vert
// RUN: cmp %t.vert %t.expected.vert
// With -o FILE the output is written as usual and the diff printed beside it.
// RUN: %stereoshift --diff %s -o %t.written.vert | %rmchecks | FileCheck %s --check-prefix=WRITTEN
// RUN: cmp %t.written.vert %t.expected.vert
// CHECK: --- {{.*}}diff.vert
// CHECK-NEXT: +++ {{.*}}diff.vert
// CHECK-NEXT: @@ -{{[0-9]+}},{{[0-9]+}} +{{[0-9]+}},{{[0-9]+}} @@
// CHECK: -void main()
// CHECK-NEXT: +void main_stereoshift_mono()
// CHECK: +// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// CHECK: +    main_stereoshift_mono();
// CHECK: +// ---- end stereoshift ----
// CHECK-NOT: #version
// WRITTEN: +++ {{.*}}written.vert
uniform mat4 mvp;
in vec4 position;
void main()
{
    gl_Position = mvp * position;
}
