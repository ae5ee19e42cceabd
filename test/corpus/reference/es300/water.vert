#version 300 es
// stereoshift-expect: shift
// Water-surface vertex shader: Gerstner-style waves; also outputs the clip position and screen UVs derived from it (halo case).

precision highp float;

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec2 aTexCoord;

uniform highp mat4 uModel;
uniform highp mat4 uViewProj;
uniform highp float uTime;
uniform highp vec4 uWave;   // xy = direction, z = amplitude, w = wavelength

out highp vec4 vClipPos;
out highp vec2 vScreenUV;
out mediump vec2 vTexCoord;
out mediump vec3 vNormal;

/* ---- stereoshift ---- */ highp vec4 stereoshift_shifted_position(highp vec4 stereoshift_p); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    float k = 6.2831853 / uWave.w;
    float phase = k * dot(uWave.xy, world.xz) - uTime * 1.5;
    world.y += uWave.z * sin(phase);
    vec2 slope = uWave.xy * (uWave.z * k * cos(phase));
    vNormal = normalize(vec3(-slope.x, 1.0, -slope.y));

    vTexCoord = aTexCoord + uWave.xy * uTime * 0.02;
    gl_Position = uViewProj * world;
    vClipPos = gl_Position;
    vScreenUV = stereoshift_shifted_position(gl_Position).xy / stereoshift_shifted_position(gl_Position).w * 0.5 + 0.5;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
highp vec4 stereoshift_shifted_position(highp vec4 stereoshift_p)
{
    if (eyeSign != 0.0 && abs(stereoshift_p.w - 1.0) > 9.99999975e-06 && !isinf(stereoshift_p.w))
    {
        stereoshift_p.x = stereoshift_p.x + (eyeSign * separation) * (stereoshift_p.w - convergence);
    }
    return stereoshift_p;
}
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
    vClipPos = gl_Position;
}
// ---- end stereoshift ----
