#version 330

invariant gl_Position;

uniform mat4 uLightMVP;
uniform float uDepthBias;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out vec2 vTexCoord;
in vec2 aTexCoord;
layout(location = 0) in vec3 aPosition;

void main()
{
    vTexCoord = aTexCoord;
    vec4 clip = uLightMVP * vec4(aPosition, 1.0);
    clip.z += (uDepthBias * clip.w);
    gl_Position = clip;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _81 = gl_Position.w - convergence;
        float _82 = eyeSign * separation;
        float _83 = _82 * _81;
        float _84 = gl_Position.x + _83;
        gl_Position.x = _84;
    }
}

