#version 330
// stereoshift-expect: shift
// Skinned character vertex shader: four-bone linear blend skinning from a bone matrix array.

const int MAX_BONES = 64;

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
in vec2 aTexCoord;
in vec4 aBoneWeights;
in ivec4 aBoneIndices;

uniform mat4 uBones[MAX_BONES];
uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProjection;

out vec3 vNormal;
out vec2 vTexCoord;
out float vViewDepth;

void main_stereoshift_mono()
{
    mat4 skin = uBones[aBoneIndices.x] * aBoneWeights.x
              + uBones[aBoneIndices.y] * aBoneWeights.y
              + uBones[aBoneIndices.z] * aBoneWeights.z
              + uBones[aBoneIndices.w] * aBoneWeights.w;

    vec4 world = uModel * skin * vec4(aPosition, 1.0);
    vec4 viewPos = uView * world;

    vNormal = normalize(mat3(uModel) * mat3(skin) * aNormal);
    vTexCoord = aTexCoord;
    vViewDepth = -viewPos.z;
    gl_Position = uProjection * viewPos;
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
