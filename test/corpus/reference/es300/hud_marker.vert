#version 300 es
// stereoshift-expect: shift
// HUD objective-marker vertex shader: a 2D icon placed at eye depth d with vec4(p.xy*d, z, d).

precision highp float;

layout(location = 0) in vec2 aCorner;
layout(location = 1) in vec2 aTexCoord;

uniform highp vec2 uMarkerNdc;      // projected marker centre in NDC
uniform highp vec2 uMarkerHalfSize; // half extent in NDC
uniform highp float uMarkerDepth;   // eye-space depth d of the tracked object
uniform highp float uDepthZ;        // matching clip z / d for the depth test

out mediump vec2 vTexCoord;
out mediump float vFade;

void main_stereoshift_mono()
{
    vec2 p = uMarkerNdc + aCorner * uMarkerHalfSize;
    float d = max(uMarkerDepth, 0.1);
    vTexCoord = aTexCoord;
    vFade = clamp(d / 50.0, 0.3, 1.0);
    gl_Position = vec4(p.xy * d, uDepthZ * d, d);
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
