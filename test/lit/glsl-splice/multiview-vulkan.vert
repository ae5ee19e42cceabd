#version 450
// --eye-source multiview on a Vulkan GLSL vertex shader, spliced into its own text: the eye sign is
// gl_ViewIndex's (exactly -1 for view 0, +1 for view 1, as the IR derives it), GL_EXT_multiview is
// required in a marked block after #version, and separation and convergence stay in the eye block.
// Every other byte as written; the output compiles for Vulkan; --verify runs each view against the
// exact shift.
// RUN: %stereoshift --eye-source multiview --validate-each --verify %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -V -S vert %t.vert -o %t.spv
// RUN: %rmchecks %s > %t.in.vert && %rmchecks %t.vert > %t.out.vert
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.vert %t.out.vert
// With --swap-eyes view 0 is the right eye.
// RUN: %stereoshift --eye-source multiview --swap-eyes %s -o - | %rmchecks | FileCheck %s --check-prefix=SWAP
// NOTE-NOT: re-emitted
// CHECK:      {{^}}#version 450
// CHECK-NEXT: {{^}}// ---- stereoshift: extensions (injected) ----
// CHECK-NEXT: {{^}}#extension GL_EXT_multiview : require
// CHECK-NEXT: {{^}}// ---- end stereoshift ----
// CHECK:      if ((gl_ViewIndex != 0 ? 1.0 : -1.0) != 0.0 && abs(gl_Position.w - 1.0) >
// CHECK:      gl_Position.x + ((gl_ViewIndex != 0 ? 1.0 : -1.0) * stereo.separation) * (gl_Position.w - stereo.convergence);
// SWAP:       gl_Position.x + ((gl_ViewIndex != 0 ? -1.0 : 1.0) * stereo.separation)
// REPORT: "mode": "multiview"
// REPORT: "route": "glsl-source-splice"
// REPORT: "verified": true
layout(set = 0, binding = 0) uniform Scene {
    mat4 viewProjection;
    mat4 model;
} scene;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inColor;
layout(location = 0) out vec3 outColor;
void main()
{
    outColor = inColor;
    gl_Position = scene.viewProjection * scene.model * vec4(inPosition, 1.0);
}
