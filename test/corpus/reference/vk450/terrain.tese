#version 450
layout(quads, ccw, fractional_even_spacing) in;

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform TerrainUBO
{
    mat4 viewProj;
    vec4 cameraPos;
    vec4 terrainScale;
    vec4 viewport;
} terrain;

layout(set = 0, binding = 2, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(set = 0, binding = 1) uniform sampler2D heightMap;

layout(location = 0) in vec2 inUV[];
layout(location = 0) out vec2 outUV;
layout(location = 1) out float outHeight;

void main()
{
    vec2 t = gl_TessCoord.xy;
    vec2 uv = mix(mix(inUV[0], inUV[1], vec2(t.x)), mix(inUV[3], inUV[2], vec2(t.x)), vec2(t.y));
    vec4 pos = mix(mix(gl_in[0].gl_Position, gl_in[1].gl_Position, vec4(t.x)), mix(gl_in[3].gl_Position, gl_in[2].gl_Position, vec4(t.x)), vec4(t.y));
    float h = textureLod(heightMap, uv, 0.0).x;
    pos.y += (h * terrain.terrainScale.y);
    outUV = uv;
    outHeight = h;
    vec4 _115 = terrain.viewProj * pos;
    gl_Position = _115;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _146 = gl_Position.w - stereo.convergence;
        precise float _147 = stereo.eyeSign * stereo.separation;
        precise float _148 = _147 * _146;
        precise float _149 = gl_Position.x + _148;
        gl_Position.x = _149;
    }
}

