#version 300 es
// stereoshift-expect: shift
// Camera-facing particle billboard vertex shader: expands instanced quads along camera right/up vectors.

precision highp float;

layout(location = 0) in vec2 aCorner;          // per-vertex quad corner in [-0.5, 0.5]
layout(location = 1) in vec4 aCenterSize;      // per-instance: xyz centre, w size
layout(location = 2) in vec4 aColor;           // per-instance colour
layout(location = 3) in float aRotation;       // per-instance rotation in radians

uniform highp mat4 uViewProj;
uniform highp vec3 uCameraRight;
uniform highp vec3 uCameraUp;

out mediump vec2 vUV;
out mediump vec4 vColor;

void main_stereoshift_mono()
{
    float s = sin(aRotation);
    float c = cos(aRotation);
    vec2 corner = vec2(c * aCorner.x - s * aCorner.y, s * aCorner.x + c * aCorner.y);

    vec3 world = aCenterSize.xyz
               + uCameraRight * corner.x * aCenterSize.w
               + uCameraUp * corner.y * aCenterSize.w;

    vUV = aCorner + 0.5;
    vColor = aColor;
    gl_Position = uViewProj * vec4(world, 1.0);
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
