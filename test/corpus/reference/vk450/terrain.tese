#version 450
// stereoshift-expect: shift
// Terrain tessellation evaluation shader: bilinear patch interpolation, height-map displacement, perspective projection.

layout(quads, fractional_even_spacing, ccw) in;

layout(set = 0, binding = 0) uniform TerrainUBO {
    mat4 viewProj;
    vec4 cameraPos;
    vec4 terrainScale;
    vec4 viewport;
} terrain;

layout(set = 0, binding = 1) uniform sampler2D heightMap;

layout(location = 0) in vec2 inUV[];

layout(location = 0) out vec2 outUV;
layout(location = 1) out float outHeight;

void main_stereoshift_mono()
{
    vec2 t = gl_TessCoord.xy;
    vec2 uv = mix(mix(inUV[0], inUV[1], t.x), mix(inUV[3], inUV[2], t.x), t.y);
    vec4 pos = mix(mix(gl_in[0].gl_Position, gl_in[1].gl_Position, t.x),
                   mix(gl_in[3].gl_Position, gl_in[2].gl_Position, t.x), t.y);

    float h = textureLod(heightMap, uv, 0.0).r;
    pos.y += h * terrain.terrainScale.y;

    outUV = uv;
    outHeight = h;
    gl_Position = terrain.viewProj * pos;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 2, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
void main()
{
    main_stereoshift_mono();
    if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
        gl_Position.x = stereoshift_x;
    }
}
// ---- end stereoshift ----
