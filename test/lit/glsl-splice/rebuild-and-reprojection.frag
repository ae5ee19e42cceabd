#version 330 core
// deferred-unprojection's matrix form followed by a re-projection, in a GLSL 330 fragment shader's own
// text: the world position rebuilt through uInvViewProj (corrected: stereoshift_unproject_<matrix>)
// is marched along a reflected ray, each step projected back through uViewProj and the depth
// texture read where it lands: that projection goes through the re-projection helper (x +
// e*S*(w - C): this eye's screen, whose depth it reads). The shadow lookup of the same position
// through uLightViewProj reads the shadow map (drawn once for both eyes): left as it is. Every other
// byte as written: undoing the marked edits gives the input back.
// RUN: %stereoshift --validate-each %s -o %t.frag --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S frag %t.frag
// RUN: %rmchecks %s > %t.in.frag && %rmchecks %t.frag > %t.out.frag
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.frag %t.out.frag
// NOTE-NOT: re-emitted
// CHECK:      vec4 q = stereoshift_unproject_uInvViewProj(uInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0));
// CHECK:      vec4 lightClip = uLightViewProj * vec4(position, 1.0);
// CHECK:      vec4 clip = stereoshift_reproject_uViewProj(uViewProj * vec4(marched, 1.0));
// REPORT:     "construct": "matrix * rebuilt position, read at in the depth texture",
// REPORT-NOT: "construct": "matrix * rebuilt position, read at in the depth texture",

uniform mat4 uInvViewProj;
uniform mat4 uViewProj;
uniform mat4 uLightViewProj;
uniform vec2 uInvViewportSize;
uniform sampler2D uDepth;
uniform sampler2D uColor;
uniform sampler2D uNormal;
uniform sampler2DShadow uShadowMap;

in vec2 vUV;
out vec4 fragColor;

void main()
{
    float depth = texture(uDepth, vUV).r;
    vec2 ndc = gl_FragCoord.xy * uInvViewportSize * 2.0 - 1.0;
    vec4 q = uInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    vec3 position = q.xyz / q.w;
    vec4 lightClip = uLightViewProj * vec4(position, 1.0);
    float lit = texture(uShadowMap, lightClip.xyz / lightClip.w * 0.5 + 0.5);
    vec3 normal = normalize(texture(uNormal, vUV).xyz * 2.0 - 1.0);
    vec3 direction = reflect(normalize(position), normal);
    vec3 marched = position;
    vec3 reflected = vec3(0.0);
    for (int i = 0; i < 24; ++i) {
        marched += direction * 0.25;
        vec4 clip = uViewProj * vec4(marched, 1.0);
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (texture(uDepth, uv).r * 2.0 - 1.0 < clip.z / clip.w) {
            reflected = texture(uColor, uv).rgb;
            break;
        }
    }
    fragColor = vec4(reflected * lit, 1.0);
}
