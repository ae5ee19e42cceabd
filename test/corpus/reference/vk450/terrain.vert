#version 450
// stereoshift-expect: intermediate
// Terrain patch vertex shader: passes grid control points in world space to the tessellation control stage.

layout(location = 0) in vec2 inGridPos;   // xz on the terrain grid
layout(location = 1) in vec2 inUV;

layout(set = 0, binding = 0) uniform TerrainUBO {
    mat4 viewProj;
    vec4 cameraPos;
    vec4 terrainScale;   // x = horizontal scale, y = height scale, z = target edge pixels
    vec4 viewport;
} terrain;

layout(location = 0) out vec2 outUV;

void main()
{
    outUV = inUV;
    gl_Position = vec4(inGridPos.x * terrain.terrainScale.x, 0.0, inGridPos.y * terrain.terrainScale.x, 1.0);
}
