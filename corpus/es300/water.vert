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

void main()
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
    vScreenUV = gl_Position.xy / gl_Position.w * 0.5 + 0.5;
}
