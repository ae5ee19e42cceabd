#version 300 es
// stereoshift-expect: shift
// Instanced rock-field vertex shader: per-instance model matrix attribute plus gl_InstanceID tint variation.

precision highp float;

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;
layout(location = 3) in mat4 aInstanceModel;   // locations 3..6, divisor 1

uniform highp mat4 uViewProj;
uniform mediump vec3 uTintA;
uniform mediump vec3 uTintB;

out mediump vec3 vNormal;
out mediump vec2 vTexCoord;
out mediump vec3 vTint;

float hash(int n)
{
    return fract(sin(float(n) * 12.9898) * 43758.5453);
}

void main_stereoshift_mono()
{
    vec4 world = aInstanceModel * vec4(aPosition, 1.0);
    vNormal = normalize(mat3(aInstanceModel) * aNormal);
    vTexCoord = aTexCoord;
    vTint = mix(uTintA, uTintB, hash(gl_InstanceID));
    gl_Position = uViewProj * world;
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
