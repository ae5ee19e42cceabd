#version 330

invariant gl_Position;

uniform mat4 uView;
uniform mat4 uProjection;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec3 aPosition;
out vec3 vDirection;

void main()
{
    mat3 _22 = mat3(uView[0].xyz, uView[1].xyz, uView[2].xyz);
    mat4 rotationOnly = mat4(vec4(_22[0].x, _22[0].y, _22[0].z, 0.0), vec4(_22[1].x, _22[1].y, _22[1].z, 0.0), vec4(_22[2].x, _22[2].y, _22[2].z, 0.0), vec4(0.0, 0.0, 0.0, 1.0));
    vec4 pos = (uProjection * rotationOnly) * vec4(aPosition, 1.0);
    vDirection = aPosition;
    gl_Position = pos.xyww;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _95 = gl_Position.w - convergence;
        float _96 = eyeSign * separation;
        float _97 = _96 * _95;
        float _98 = gl_Position.x + _97;
        gl_Position.x = _98;
    }
}

