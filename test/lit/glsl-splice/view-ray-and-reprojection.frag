#version 330 core
// deferred-unprojection's view-ray form in a GLSL 330 fragment shader's own text: the local the
// corrected position is assigned to gets its right-hand side through stereoshift_view_ray_<local>()
// (x - e*S*(|z| - C) / P00, P00 read from the projection the shader re-projects with), and that
// re-projection, a sample of the corrected position sent back to the screen, goes through
// stereoshift_reproject_<matrix>() (x + e*S*(w - C): this eye's screen again). Every other byte as
// written: undoing the marked edits gives the input back.
// RUN: %stereoshift --validate-each %s -o %t.frag --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S frag %t.frag
// RUN: %rmchecks %s > %t.in.frag && %rmchecks %t.frag > %t.out.frag
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.frag %t.out.frag
// NOTE-NOT: re-emitted
// CHECK:      {{^}}/* ---- stereoshift ---- */ vec4 stereoshift_reproject_uProjection(vec4 stereoshift_q); /* ---- end stereoshift ---- */ float contactShadow(vec3 position, vec3 toLight)
// CHECK:      vec4 clip = stereoshift_reproject_uProjection(uProjection * vec4(position + toLight * (0.05 * float(i)), 1.0));
// CHECK:      {{^}}/* ---- stereoshift ---- */ vec3 stereoshift_view_ray_position(vec3 stereoshift_p); /* ---- end stereoshift ---- */ void main()
// CHECK:      vec3 position = stereoshift_view_ray_position(vRay * /* linear */ texture(uViewDepth, vUV).r); // view space
// CHECK:      uniform float eyeSign;
// CHECK-NEXT: uniform float separation;
// CHECK-NEXT: uniform float convergence;
// CHECK-NEXT: vec4 stereoshift_reproject_uProjection(vec4 stereoshift_q)
// CHECK-NEXT: {
// CHECK-NEXT:     return eyeSign != 0.0 ? vec4(stereoshift_q.x + (eyeSign * separation) * (stereoshift_q.w - convergence), stereoshift_q.yzw) : stereoshift_q;
// CHECK-NEXT: }
// CHECK-NEXT: vec3 stereoshift_view_ray_position(vec3 stereoshift_p)
// CHECK-NEXT: {
// CHECK-NEXT:     if (eyeSign != 0.0)
// CHECK-NEXT:         stereoshift_p.x = stereoshift_p.x - ((eyeSign * separation) * (abs(stereoshift_p.z) - convergence)) * (1.0 / uProjection[0][0]);
// CHECK-NEXT:     return stereoshift_p;
// CHECK-NEXT: }
// REPORT: "construct": "matrix * view-ray position",
// REPORT: "construct": "view ray * depth",
// REPORT: "projection_scale": "uProjection[0][0]"
// REPORT: "route": "glsl-source-splice"

uniform sampler2D uViewDepth;   // positive view depth
uniform sampler2D uShadowless;
uniform mat4 uProjection;
uniform vec3 uLightView;

in vec2 vUV;
in vec3 vRay;                   // interpolated frustum ray, z = -1
out vec4 fragColor;

float contactShadow(vec3 position, vec3 toLight)
{
    float shadow = 0.0;
    for (int i = 1; i <= 4; ++i) {
        vec4 clip = uProjection * vec4(position + toLight * (0.05 * float(i)), 1.0);
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        float sceneDepth = texture(uViewDepth, uv).r;
        shadow += sceneDepth < clip.w - 0.02 ? 0.25 : 0.0;
    }
    return shadow;
}

void main()
{
    vec3 position = vRay * /* linear */ texture(uViewDepth, vUV).r; // view space
    vec3 toLight = normalize(uLightView - position);
    fragColor = vec4(texture(uShadowless, vUV).rgb * (1.0 - contactShadow(position, toLight)), 1.0);
}
