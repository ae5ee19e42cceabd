#version 300 es

invariant gl_Position;

uniform mat4 u_mvpMatrix;
uniform mat3 u_normalMatrix;
uniform vec3 u_lightDirection;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

in vec4 a_position;
out mediump vec2 v_texCoord;
in mediump vec2 a_texCoord;
out mediump float v_diffuse;
in vec3 a_normal;

void main()
{
    vec4 _20 = u_mvpMatrix * a_position;
    gl_Position = _20;
    v_texCoord = a_texCoord;
    v_diffuse = max(dot(normalize(u_normalMatrix * a_normal), u_lightDirection), 0.0);
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _75 = gl_Position.w - convergence;
        float _76 = eyeSign * separation;
        float _77 = _76 * _75;
        float _78 = gl_Position.x + _77;
        gl_Position.x = _78;
    }
}

