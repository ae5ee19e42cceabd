#version 330

invariant gl_Position;

uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProjection;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec4 aTangent;
out vec2 vUV;
layout(location = 2) in vec2 aTexCoords;
out vec3 vTangentEye;
out vec3 vTangentPos;

void main()
{
    vec4 world = uModel * vec4(aPos, 1.0);
    vec3 n = normalize(mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz) * aNormal);
    vec3 t = normalize(mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz) * aTangent.xyz);
    vec3 b = cross(n, t) * aTangent.w;
    mat3 toTangent = transpose(mat3(vec3(t), vec3(b), vec3(n)));
    mat4 _155 = inverse(uView);
    _155[3] = _155[3] + vec4((inverse(uProjection * uView) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
    vec3 eye = _155[3].xyz;
    vUV = aTexCoords;
    vTangentEye = toTangent * eye;
    vTangentPos = toTangent * world.xyz;
    mat4 _117 = uProjection * uView;
    vec4 _119 = _117 * world;
    gl_Position = _119;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _149 = gl_Position.w - convergence;
        float _150 = eyeSign * separation;
        float _151 = _150 * _149;
        float _152 = gl_Position.x + _151;
        gl_Position.x = _152;
    }
}

