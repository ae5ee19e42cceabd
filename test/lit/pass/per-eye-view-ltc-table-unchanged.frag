// per-eye-view: an area light's linearly transformed cosines read two tables at
// `vec2(roughness, sqrt(1 - dot(N, V))) * LUT_SCALE + LUT_BIAS`: a lookup *at* a function of V (no
// per-pixel texture coordinate is moved along it), so the camera stays mono and the shader is
// copied. Before, the constant bias added to the V-derived coordinate read as a parallax offset.
// RUN: %stereoshift --validate-each %s -o %t.frag --report %t.json
// RUN: cmp %s %t.frag
// RUN: FileCheck %s --input-file %t.json
// CHECK: "uniform": "uCameraPos",
// CHECK: "use": "texture looked up along a direction from it (reflection, BRDF table), no texture coordinate moved along it"
// CHECK: "result": "unchanged"
#version 330 core
in vec3 vWorldPos;
in vec3 vNormal;
out vec4 FragColor;

uniform vec3 uCameraPos;
uniform float uRoughness;
uniform vec3 uLightColor;
uniform sampler2D uLtcMatrix;
uniform sampler2D uLtcMagnitude;

const float LUT_SIZE = 64.0;
const float LUT_SCALE = (LUT_SIZE - 1.0) / LUT_SIZE;
const float LUT_BIAS = 0.5 / LUT_SIZE;

void main()
{
    vec3 N = normalize(vNormal);
    vec3 V = normalize(uCameraPos - vWorldPos);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    vec2 uv = vec2(uRoughness, sqrt(1.0 - NdotV));
    uv = uv * LUT_SCALE + LUT_BIAS;
    vec4 t1 = texture(uLtcMatrix, uv);
    vec4 t2 = texture(uLtcMagnitude, uv);
    mat3 Minv = mat3(vec3(t1.x, 0.0, t1.y), vec3(0.0, 1.0, 0.0), vec3(t1.z, 0.0, t1.w));
    vec3 spec = (Minv * N) * t2.x;
    FragColor = vec4(uLightColor * spec, 1.0);
}
