#version 300 es
// stereoshift-expect: shift
// G-buffer geometry-pass vertex shader: world normal and tangent frame for normal mapping.

precision highp float;

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aTexCoord;

uniform highp mat4 uModel;
uniform highp mat4 uViewProj;

out mediump vec3 vNormal;
out mediump vec3 vTangent;
out mediump vec3 vBitangent;
out mediump vec2 vTexCoord;

void main_stereoshift_mono()
{
    mat3 m = mat3(uModel);
    vNormal = normalize(m * aNormal);
    vTangent = normalize(m * aTangent.xyz);
    vBitangent = cross(vNormal, vTangent) * aTangent.w;
    vTexCoord = aTexCoord;
    gl_Position = uViewProj * uModel * vec4(aPosition, 1.0);
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
