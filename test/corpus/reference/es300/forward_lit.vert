#version 300 es
// stereoshift-expect: shift
// Mobile forward-lit mesh vertex shader: per-vertex hemisphere ambient, perspective MVP.

precision highp float;

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;

uniform highp mat4 uModel;
uniform highp mat4 uViewProj;
uniform mediump vec3 uSkyColor;
uniform mediump vec3 uGroundColor;

out mediump vec3 vNormal;
out mediump vec3 vAmbient;
out mediump vec2 vTexCoord;

void main_stereoshift_mono()
{
    vec3 n = normalize(mat3(uModel) * aNormal);
    vNormal = n;
    vAmbient = mix(uGroundColor, uSkyColor, n.y * 0.5 + 0.5);
    vTexCoord = aTexCoord;
    gl_Position = uViewProj * (uModel * vec4(aPosition, 1.0));
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
