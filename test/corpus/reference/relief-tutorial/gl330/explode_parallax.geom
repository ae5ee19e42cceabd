#version 330 core
// stereoshift-expect: shift
// Exploding parallax-mapped model, geometry stage: pushes each triangle out along its face normal and passes the tangent-space vectors on.
layout (triangles) in;
layout (triangle_strip, max_vertices = 3) out;

in VS_OUT {
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} gs_in[];

out GS_OUT {
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} gs_out;

uniform float time;

vec4 explode(vec4 position, vec3 normal)
{
    float magnitude = 0.2;
    vec3 direction = normal * ((sin(time) + 1.0) / 2.0) * magnitude;
    return position + vec4(direction, 0.0);
}

vec3 faceNormal()
{
    vec3 a = vec3(gl_in[0].gl_Position) - vec3(gl_in[1].gl_Position);
    vec3 b = vec3(gl_in[2].gl_Position) - vec3(gl_in[1].gl_Position);
    return normalize(cross(a, b));
}

/* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main()
{
    vec3 normal = faceNormal();
    for (int i = 0; i < 3; ++i) {
        gl_Position = explode(gl_in[i].gl_Position, normal);
        gs_out.TexCoords = gs_in[i].TexCoords;
        gs_out.TangentViewPos = gs_in[i].TangentViewPos;
        gs_out.TangentFragPos = gs_in[i].TangentFragPos;
        { stereoshift_shiftPosition(); EmitVertex(); }
    }
    EndPrimitive();
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
void stereoshift_shiftPosition()
{
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
