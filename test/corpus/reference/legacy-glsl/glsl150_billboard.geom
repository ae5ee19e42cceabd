#version 150
layout(points) in;
layout(max_vertices = 4, triangle_strip) out;

invariant gl_Position;

uniform mat4 projection;
uniform float halfSize;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out vec2 cornerUv;
in vec4 viewCenter[1];

void main()
{
    for (int i = 0; i < 4; i++)
    {
        vec2 corner = (vec2(float(i % 2), float(i / 2)) * 2.0) - vec2(1.0);
        cornerUv = (corner * 0.5) + vec2(0.5);
        vec2 _64 = corner * halfSize;
        float _66 = _64.x;
        float _67 = _64.y;
        vec4 _68 = vec4(_66, _67, 0.0, 0.0);
        vec4 _69 = viewCenter[0] + _68;
        vec4 _70 = projection * _69;
        gl_Position = _70;
        if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
        {
            float _98 = gl_Position.w - convergence;
            float _99 = eyeSign * separation;
            float _100 = _99 * _98;
            float _101 = gl_Position.x + _100;
            gl_Position.x = _101;
        }
        EmitVertex();
    }
    EndPrimitive();
}

