#version 330
layout(triangles) in;
layout(max_vertices = 8, line_strip) out;

invariant gl_Position;

uniform mat4 uViewProj;
uniform float uNormalLength;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out vec3 gColor;
in VertexData
{
    vec3 normal;
} gsIn[3];


void emitLine(vec3 from, vec3 dir, vec3 color)
{
    gColor = color;
    vec4 _36 = vec4(from, 1.0);
    vec4 _37 = uViewProj * _36;
    gl_Position = _37;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _151 = gl_Position.w - convergence;
        float _152 = eyeSign * separation;
        float _153 = _152 * _151;
        float _154 = gl_Position.x + _153;
        gl_Position.x = _154;
    }
    EmitVertex();
    gColor = color;
    vec3 _47 = dir * uNormalLength;
    vec3 _48 = from + _47;
    float _49 = _48.x;
    float _50 = _48.y;
    float _51 = _48.z;
    vec4 _52 = vec4(_49, _50, _51, 1.0);
    vec4 _53 = uViewProj * _52;
    gl_Position = _53;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _175 = gl_Position.w - convergence;
        float _176 = eyeSign * separation;
        float _177 = _176 * _175;
        float _178 = gl_Position.x + _177;
        gl_Position.x = _178;
    }
    EmitVertex();
    EndPrimitive();
}

void main()
{
    for (int i = 0; i < 3; i++)
    {
        vec3 param = gl_in[i].gl_Position.xyz;
        vec3 param_1 = gsIn[i].normal;
        vec3 param_2 = vec3(1.0, 1.0, 0.0);
        emitLine(param, param_1, param_2);
    }
    vec3 p0 = gl_in[0].gl_Position.xyz;
    vec3 p1 = gl_in[1].gl_Position.xyz;
    vec3 p2 = gl_in[2].gl_Position.xyz;
    vec3 faceNormal = normalize(cross(p1 - p0, p2 - p0));
    vec3 param_3 = ((p0 + p1) + p2) / vec3(3.0);
    vec3 param_4 = faceNormal;
    vec3 param_5 = vec3(0.0, 1.0, 1.0);
    emitLine(param_3, param_4, param_5);
}

