#version 330
// stereoshift-expect: per-eye-view
// Parallax-occlusion-mapped wall vertex shader: tangent-space view vector from uCameraPos minus the world position.

layout(location = 0) in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
in vec2 aTexCoord;

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec3 uCameraPos;
uniform vec3 uLightPos;

out vec2 vTexCoord;
out vec3 vViewTS;
out vec3 vLightTS;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    vec3 b = cross(n, t) * aTangent.w;
    mat3 worldToTangent = transpose(mat3(t, b, n));

    vViewTS = worldToTangent * (uCameraPos - world.xyz);
    vLightTS = worldToTangent * (uLightPos - world.xyz);
    vTexCoord = aTexCoord;
    gl_Position = uViewProj * world;
}
