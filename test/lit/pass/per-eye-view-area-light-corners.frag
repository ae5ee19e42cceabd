// per-eye-view --per-eye-specular on an area light's linearly transformed cosines: the camera gets
// its per-eye centre, the light polygon's corners do not, though a direction from each reaches a
// table lookup too (through the LTC matrix and the edge integral): several elements of one array
// each subtracted from the surface point are points of the scene, and there is one camera. The
// corners' name says nothing (`quad`), so only that structure tells them apart.
// RUN: %stereoshift --per-eye-specular --validate-each %s -o %t.frag --report %t.json
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %rmchecks %t.frag | FileCheck %s
// REPORT: "uniform": "viewPosition",
// REPORT: "use": "one of 4 elements of an array each subtracted from the surface point"
// REPORT: "result": "changed"
// CHECK-NOT: stereoshift_eye_quad
// CHECK: normalize(stereoshift_eye_viewPosition(viewPosition) - fragWorldPos)
// CHECK-NOT: stereoshift_eye_quad
// CHECK: return stereoshift_camera + vec3(eyeOffsetX, eyeOffsetY, eyeOffsetZ);
// CHECK-NOT: stereoshift_eye_quad
#version 330
uniform vec3 viewPosition;
uniform vec3 quad[4];
uniform float roughness;
uniform sampler2D ltcMatrix;
uniform sampler2D ltcAmplitude;
in vec3 fragWorldPos;
in vec3 fragNormal;
out vec4 fragColor;

vec3 edgeIntegral(vec3 v1, vec3 v2)
{
    float x = dot(v1, v2);
    float y = abs(x);
    float a = 0.8543985 + (0.4965155 + 0.0145206 * y) * y;
    float b = 3.4175940 + (4.1616724 + y) * y;
    float v = a / b;
    float thetaSintheta = (x > 0.0) ? v : 0.5 * inversesqrt(max(1.0 - x * x, 1e-7)) - v;
    return cross(v1, v2) * thetaSintheta;
}

float areaLight(vec3 N, vec3 V, vec3 P, mat3 Minv)
{
    vec3 T1 = normalize(V - N * dot(V, N));
    vec3 T2 = cross(N, T1);
    Minv = Minv * transpose(mat3(T1, T2, N));
    vec3 L0 = normalize(Minv * (quad[0] - P));
    vec3 L1 = normalize(Minv * (quad[1] - P));
    vec3 L2 = normalize(Minv * (quad[2] - P));
    vec3 L3 = normalize(Minv * (quad[3] - P));
    vec3 vsum = edgeIntegral(L0, L1) + edgeIntegral(L1, L2) + edgeIntegral(L2, L3) + edgeIntegral(L3, L0);
    float len = length(vsum);
    float z = vsum.z / len;
    vec2 uv = vec2(z * 0.5 + 0.5, len) * (63.0 / 64.0) + 0.5 / 64.0;
    float scale = texture(ltcAmplitude, uv).w;
    return len * scale;
}

void main()
{
    vec3 N = normalize(fragNormal);
    vec3 V = normalize(viewPosition - fragWorldPos);
    float cosTheta = dot(N, V);
    vec2 uv = vec2(roughness, sqrt(1.0 - cosTheta)) * (63.0 / 64.0) + 0.5 / 64.0;
    vec4 t = texture(ltcMatrix, uv);
    mat3 Minv = mat3(vec3(t.x, 0.0, t.y), vec3(0.0, 1.0, 0.0), vec3(t.z, 0.0, t.w));
    float spec = areaLight(N, V, fragWorldPos, Minv);
    float diff = areaLight(N, V, fragWorldPos, mat3(1.0));
    fragColor = vec4(vec3(spec + diff), 1.0);
}
