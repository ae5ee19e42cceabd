#version 400 compatibility
// The compatibility profile past 330 (a GL 4 engine that kept its fixed-function matrices and
// attributes): glslang makes no SPIR-V from that profile, so the analysis reads the same core
// translation as 1xx, at the shader's own version (dvec4 needs 400); the output is the original
// text with the shift, checked by glslang's compatibility profile and run by verify.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// RUN: %stereoshift verify %s | FileCheck %s --check-prefix=VERIFY
// RUN: %stereoshift %s --target spirv -o %t.spv
// RUN: spirv-val %t.spv
// CHECK:      {{^}}void main_stereoshift_mono()
// CHECK:      gl_Position = ftransform();
// CHECK-NEXT: uv = vec2(gl_MultiTexCoord0.xy) + vec2(offsetD.xy);
// CHECK-NEXT: gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
// CHECK:      precise float stereoshift_x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NOT:  stereoshift_Vertex
// REPORT: "classification": "perspective"
// REPORT: "dialect_reason": "#version 400 compatibility"
// VERIFY: verified
uniform dvec4 offsetD;
out vec2 uv;
void main()
{
    gl_Position = ftransform();
    uv = vec2(gl_MultiTexCoord0.xy) + vec2(offsetD.xy);
    gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
}
