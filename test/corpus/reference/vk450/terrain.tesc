#version 450
// stereoshift-expect: intermediate
// Terrain tessellation control shader: distance-based tessellation levels for 4-vertex quad patches.

layout(vertices = 4) out;

layout(set = 0, binding = 0) uniform TerrainUBO {
    mat4 viewProj;
    vec4 cameraPos;
    vec4 terrainScale;
    vec4 viewport;
} terrain;

layout(location = 0) in vec2 inUV[];
layout(location = 0) out vec2 outUV[];

float edgeLevel(vec3 a, vec3 b)
{
    float dist = distance((a + b) * 0.5, terrain.cameraPos.xyz);
    return clamp(terrain.terrainScale.z * 64.0 / dist, 1.0, 64.0);
}

void main()
{
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    outUV[gl_InvocationID] = inUV[gl_InvocationID];

    if (gl_InvocationID == 0) {
        vec3 p0 = gl_in[0].gl_Position.xyz;
        vec3 p1 = gl_in[1].gl_Position.xyz;
        vec3 p2 = gl_in[2].gl_Position.xyz;
        vec3 p3 = gl_in[3].gl_Position.xyz;
        gl_TessLevelOuter[0] = edgeLevel(p3, p0);
        gl_TessLevelOuter[1] = edgeLevel(p0, p1);
        gl_TessLevelOuter[2] = edgeLevel(p1, p2);
        gl_TessLevelOuter[3] = edgeLevel(p2, p3);
        gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
        gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
    }
}
