#version 300 es
// deferred-unprojection in an ESSL fragment shader's own text: the product that rebuilds the
// position goes through stereoshift_unproject_<matrix>() (q - InvM[0] * e*S*(1 - C*q.w), q itself
// when eyeSign is 0), every other byte as written. The helper works in highp whatever the default
// precision, and the eye parameters are highp uniforms, as the vertex stage declares them (ESSL
// links a uniform of two stages only at one precision). Undoing the marked edits gives the input.
// RUN: %stereoshift --validate-each %s -o %t.frag --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S frag %t.frag
// RUN: %rmchecks %s > %t.in.frag && %rmchecks %t.frag > %t.out.frag
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.frag %t.out.frag
// NOTE-NOT: re-emitted
// CHECK:      {{^}}/* ---- stereoshift ---- */ highp vec4 stereoshift_unproject_uInvViewProj(highp vec4 stereoshift_q); /* ---- end stereoshift ---- */ void main()
// CHECK:      highp vec4 q = stereoshift_unproject_uInvViewProj(uInvViewProj * vec4(vUV * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0));
// CHECK:      uniform highp float eyeSign;
// CHECK-NEXT: uniform highp float separation;
// CHECK-NEXT: uniform highp float convergence;
// CHECK-NEXT: highp vec4 stereoshift_unproject_uInvViewProj(highp vec4 stereoshift_q)
// CHECK-NEXT: {
// CHECK-NEXT:     return eyeSign != 0.0 ? stereoshift_q - uInvViewProj[0] * ((eyeSign * separation) * (1.0 - convergence * stereoshift_q.w)) : stereoshift_q;
// REPORT: "form": "world position from an inverse view-projection",
// REPORT: "route": "glsl-source-splice"
precision mediump float;
in vec2 vUV;
uniform highp sampler2D uDepth;
uniform highp mat4 uInvViewProj;
uniform vec3 uLightPos;
out vec4 fragColor;

void main()
{
    float depth = texture(uDepth, vUV).r;
    highp vec4 q = uInvViewProj * vec4(vUV * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    highp vec3 p = q.xyz / q.w;
    fragColor = vec4(vec3(1.0 / (1.0 + length(uLightPos - p))), 1.0);
}
