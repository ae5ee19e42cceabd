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

/* ---- stereoshift ---- */ vec3 stereoshift_eye_uCameraPos(vec3 stereoshift_camera); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    vec3 b = cross(n, t) * aTangent.w;
    mat3 worldToTangent = transpose(mat3(t, b, n));

    vViewTS = worldToTangent * (stereoshift_eye_uCameraPos(uCameraPos) - world.xyz);
    vLightTS = worldToTangent * (uLightPos - world.xyz);
    vTexCoord = aTexCoord;
    gl_Position = uViewProj * world;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
vec3 stereoshift_eye_uCameraPos(vec3 stereoshift_camera)
{
    return stereoshift_camera + (inverse(uViewProj) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz;
}
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
