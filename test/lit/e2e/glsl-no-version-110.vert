// A desktop GLSL 110 vertex shader without #version, fixed-function style (gl_Vertex,
// gl_ModelViewProjectionMatrix, gl_MultiTexCoord0, ftransform) is GLSL, never taken for HLSL.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift %s -o %t/out.vert --report %t/report.json 2> %t/log.txt || true
// RUN: FileCheck %s --input-file %t/report.json
// RUN: FileCheck %s --allow-empty --check-prefix=LOG --input-file %t/log.txt
varying vec3 normal;
varying vec4 color;
uniform float lerpAmount;
vec4 lerp(vec4 a, vec4 b, float t) { return a + (b - a) * t; }
void main()
{
  normal = normalize(gl_NormalMatrix * gl_Normal);
  color = lerp(gl_Color, vec4(1.0), lerpAmount);
  gl_TexCoord[0] = gl_MultiTexCoord0;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
// CHECK: "language": "glsl",
// CHECK-NEXT: "language_reason": "no #version; GLSL constructs: varying, vec3, vec4, gl_NormalMatrix, ... (HLSL 0, GLSL {{[0-9]+}})",
// CHECK-NEXT: "language_source": "content",
// LOG-NOT: entry point
// LOG-NOT: HLSL constructs
