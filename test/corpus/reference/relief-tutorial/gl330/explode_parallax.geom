#version 330
layout(triangles) in;
layout(max_vertices = 3, triangle_strip) out;

invariant gl_Position;

uniform float time;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out GS_OUT
{
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} gs_out;

in VS_OUT
{
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} gs_in[3];


vec3 faceNormal()
{
    vec3 a = vec3(gl_in[0].gl_Position.xyz) - vec3(gl_in[1].gl_Position.xyz);
    vec3 b = vec3(gl_in[2].gl_Position.xyz) - vec3(gl_in[1].gl_Position.xyz);
    return normalize(cross(a, b));
}

vec4 explode(vec4 position, vec3 normal)
{
    float magnitude = 0.20000000298023223876953125;
    vec3 direction = (normal * ((sin(time) + 1.0) / 2.0)) * magnitude;
    return position + vec4(direction, 0.0);
}

void main()
{
    vec3 normal = faceNormal();
    for (int i = 0; i < 3; i++)
    {
        vec4 param = gl_in[i].gl_Position;
        vec3 param_1 = normal;
        vec4 _114 = explode(param, param_1);
        gl_Position = _114;
        gs_out.TexCoords = gs_in[i].TexCoords;
        gs_out.TangentViewPos = gs_in[i].TangentViewPos;
        gs_out.TangentFragPos = gs_in[i].TangentFragPos;
        if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
        {
            float _165 = gl_Position.w - convergence;
            float _166 = eyeSign * separation;
            float _167 = _166 * _165;
            float _168 = gl_Position.x + _167;
            gl_Position.x = _168;
        }
        EmitVertex();
    }
    EndPrimitive();
}

