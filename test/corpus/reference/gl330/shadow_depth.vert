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
    if ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w)))
    {
        float _77 = gl_Position.w - convergence;
        float _78 = eyeSign * separation;
        float _79 = _78 * _77;
        float _80 = gl_Position.x + _79;
        gl_Position.x = _80;
    }
}

