#version 330 core
// An output computed from the clip position (screen-space refraction UVs), through a local that
// holds it: in the spliced text the local's reads in that assignment go
// through stereoshift_shifted_position, the position as the shift leaves it, so the outputs move
// with the geometry (no halo) and every byte outside the marked edits is the input's. A fog factor
// from w alone is the same in both eyes: left as written. --verify runs it against the exact
// stereo reference.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %rmchecks %s > %t.in.vert && %rmchecks %t.vert > %t.out.vert
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.vert %t.out.vert
// NOTE-NOT: re-emitted
// CHECK:      {{^}}/* ---- stereoshift ---- */ vec4 stereoshift_shifted_position(vec4 stereoshift_p); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
// CHECK:      gl_Position = clip;
// CHECK-NEXT: vRefractUV = (stereoshift_shifted_position(clip).xy / stereoshift_shifted_position(clip).w) * 0.5 + 0.5;
// CHECK-NEXT: vFog = clamp(clip.w * uFogScale, 0.0, 1.0);
// CHECK-NEXT: vColor = aColor;
// CHECK:      vec4 stereoshift_shifted_position(vec4 stereoshift_p)
// CHECK-NEXT: {
// CHECK-NEXT:     if (eyeSign != 0.0 && abs(stereoshift_p.w - 1.0) > 9.99999975e-06 && !isinf(stereoshift_p.w))
// CHECK-NEXT:     {
// CHECK-NEXT:         stereoshift_p.x = stereoshift_p.x + (eyeSign * separation) * (stereoshift_p.w - convergence);
// CHECK-NEXT:     }
// CHECK-NEXT:     return stereoshift_p;
// CHECK-NEXT: }
// REPORT:      "derived_outputs": [
// REPORT-NEXT:   "vRefractUV"
// REPORT-NEXT: ],
// REPORT:      "route": "glsl-source-splice"
// REPORT:      "verified": true

uniform mat4 uViewProj;
uniform float uFogScale;
in vec3 aPos;
in vec3 aColor;
out vec2 vRefractUV;
out float vFog;
out vec3 vColor;

void main()
{
    vec4 clip = uViewProj * vec4(aPos, 1.0);
    gl_Position = clip;
    vRefractUV = (clip.xy / clip.w) * 0.5 + 0.5;
    vFog = clamp(clip.w * uFogScale, 0.0, 1.0);
    vColor = aColor;
}
