#version 330

invariant gl_Position;

uniform mat4 uBones[64];
uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProjection;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

in ivec4 aBoneIndices;
in vec4 aBoneWeights;
layout(location = 0) in vec3 aPosition;
out vec3 vNormal;
layout(location = 1) in vec3 aNormal;
out vec2 vTexCoord;
in vec2 aTexCoord;
out float vViewDepth;

void main()
{
    mat4 _32 = uBones[aBoneIndices.x] * aBoneWeights.x;
    mat4 _40 = uBones[aBoneIndices.y] * aBoneWeights.y;
    mat4 _53 = mat4(_32[0] + _40[0], _32[1] + _40[1], _32[2] + _40[2], _32[3] + _40[3]);
    mat4 _61 = uBones[aBoneIndices.z] * aBoneWeights.z;
    mat4 _74 = mat4(_53[0] + _61[0], _53[1] + _61[1], _53[2] + _61[2], _53[3] + _61[3]);
    mat4 _82 = uBones[aBoneIndices.w] * aBoneWeights.w;
    mat4 skin = mat4(_74[0] + _82[0], _74[1] + _82[1], _74[2] + _82[2], _74[3] + _82[3]);
    vec4 world = (uModel * skin) * vec4(aPosition, 1.0);
    vec4 viewPos = uView * world;
    vNormal = normalize((mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz) * mat3(skin[0].xyz, skin[1].xyz, skin[2].xyz)) * aNormal);
    vTexCoord = aTexCoord;
    vViewDepth = -viewPos.z;
    vec4 _161 = uProjection * viewPos;
    gl_Position = _161;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _192 = gl_Position.w - convergence;
        float _193 = eyeSign * separation;
        float _194 = _193 * _192;
        float _195 = gl_Position.x + _194;
        gl_Position.x = _195;
    }
}

