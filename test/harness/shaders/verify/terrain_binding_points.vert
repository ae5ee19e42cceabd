// OpenGL 4.2 terrain vertex shader: a grid displaced by a height map, its matrices and terrain
// parameters in std140 blocks. OpenGL numbers texture units and uniform-block binding points apart,
// so the height map and the matrices both take binding 0 (and the normal map and the terrain block
// binding 1). No loose uniform: glslang accepts it with Vulkan rules too, where those bindings clash.
#version 420 core
layout(location = 0) in vec2 gridPos;

layout(std140, binding = 0) uniform Matrices {
    mat4 projection;
    mat4 view;
};
layout(std140, binding = 1) uniform Terrain {
    vec2 worldSize;
    float heightScale;
};
layout(binding = 0) uniform sampler2D heightMap;
layout(binding = 1) uniform sampler2D normalMap;

out vec3 vNormal;
out vec2 vUv;

void main()
{
    vUv = gridPos * 0.5 + 0.5;
    float height = textureLod(heightMap, vUv, 0.0).r * heightScale;
    vNormal = normalize(textureLod(normalMap, vUv, 0.0).xyz * 2.0 - 1.0);
    vec4 world = vec4(gridPos.x * worldSize.x, height, gridPos.y * worldSize.y, 1.0);
    gl_Position = projection * view * world;
}
