#version 330

invariant gl_Position;

uniform mat4 uModel;
uniform vec3 uCameraPos;
uniform vec3 uLightPos;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
out vec3 vViewTS;
out vec3 vLightTS;
out vec2 vTexCoord;
in vec2 aTexCoord;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz) * aNormal);
    vec3 t = normalize(mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz) * aTangent.xyz);
    vec3 b = cross(n, t) * aTangent.w;
    mat3 worldToTangent = transpose(mat3(vec3(t), vec3(b), vec3(n)));
    vViewTS = worldToTangent * ((uCameraPos + (inverse(uViewProj) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz) - world.xyz);
    vLightTS = worldToTangent * (uLightPos - world.xyz);
    vTexCoord = aTexCoord;
    vec4 _118 = uViewProj * world;
    gl_Position = _118;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _148 = gl_Position.w - convergence;
        float _149 = eyeSign * separation;
        float _150 = _149 * _148;
        float _151 = gl_Position.x + _150;
        gl_Position.x = _151;
    }
}

