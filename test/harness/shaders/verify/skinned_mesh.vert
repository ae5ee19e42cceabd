// OpenGL 3.3 skeletal animation in the tutorial manner: a loose uniform array of bone matrices,
// integer bone ids and weights per vertex, up to four bones a vertex.
#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
layout (location = 3) in ivec4 aBoneIds;
layout (location = 4) in vec4 aWeights;

const int MAX_BONES = 32;
const int MAX_BONE_INFLUENCE = 4;
uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform mat4 finalBonesMatrices[MAX_BONES];

out vec2 TexCoords;
out vec3 Normal;

void main()
{
    vec4 totalPosition = vec4(0.0);
    vec3 totalNormal = vec3(0.0);
    for (int i = 0; i < MAX_BONE_INFLUENCE; i++) {
        if (aBoneIds[i] == -1) continue;
        if (aBoneIds[i] >= MAX_BONES) {
            totalPosition = vec4(aPos, 1.0);
            break;
        }
        vec4 localPosition = finalBonesMatrices[aBoneIds[i] % MAX_BONES] * vec4(aPos, 1.0);
        totalPosition += localPosition * aWeights[i];
        totalNormal += mat3(finalBonesMatrices[aBoneIds[i] % MAX_BONES]) * aNormal * aWeights[i];
    }
    if (totalPosition == vec4(0.0)) totalPosition = vec4(aPos, 1.0);
    TexCoords = aTexCoords;
    Normal = totalNormal;
    gl_Position = projection * view * model * totalPosition;
}
