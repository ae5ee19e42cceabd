#version 450
// --eye-source push-constant on a Vulkan shader that has its own push-constant block: the eye
// parameters join that block after its last member (at the offsets the IR gives them, written out:
// GLSL 450 has `offset`), in one marked insertion before its closing brace, and the shift reads them
// through the block's instance. Every other byte as written; the output compiles for Vulkan.
// RUN: %stereoshift --eye-source push-constant --validate-each --verify %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -V -S vert %t.vert -o %t.spv
// RUN: %rmchecks %s > %t.in.vert && %rmchecks %t.vert > %t.out.vert
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.vert %t.out.vert
// NOTE-NOT: re-emitted
// CHECK:      {{^}}    vec4 tint;
// CHECK-NEXT: {{^}}/* ---- stereoshift ---- */ layout(offset = 80) float eyeSign; layout(offset = 84) float separation; layout(offset = 88) float convergence; /* ---- end stereoshift ---- */ } object;
// CHECK:      if (object.eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
// CHECK:      object.separation) * (gl_Position.w - object.convergence)
// REPORT: "declared": "push constants",
// REPORT: "route": "glsl-source-splice"
// REPORT: "verified": true
layout(set = 0, binding = 0) uniform Camera {
    mat4 viewProjection;
} camera;
layout(push_constant) uniform ObjectConstants {
    mat4 model;
    vec4 tint;
} object;
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec4 outTint;
void main()
{
    outTint = object.tint;
    gl_Position = camera.viewProjection * object.model * vec4(inPosition, 1.0);
}
