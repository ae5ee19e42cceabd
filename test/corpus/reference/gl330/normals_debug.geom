#version 330
// stereoshift-expect: shift
// Normal-visualisation geometry shader: emits a line segment per vertex plus one per face through a helper.

layout(triangles) in;
layout(line_strip, max_vertices = 8) out;

in VertexData {
    vec3 normal;
} gsIn[];

uniform mat4 uViewProj;
uniform float uNormalLength;

out vec3 gColor;

/* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void emitLine(vec3 from, vec3 dir, vec3 color)
{
    gColor = color;
    gl_Position = uViewProj * vec4(from, 1.0);
    { stereoshift_shiftPosition(); EmitVertex(); }
    gColor = color;
    gl_Position = uViewProj * vec4(from + dir * uNormalLength, 1.0);
    { stereoshift_shiftPosition(); EmitVertex(); }
    EndPrimitive();
}

void main()
{
    for (int i = 0; i < 3; ++i)
        emitLine(gl_in[i].gl_Position.xyz, gsIn[i].normal, vec3(1.0, 1.0, 0.0));

    vec3 p0 = gl_in[0].gl_Position.xyz;
    vec3 p1 = gl_in[1].gl_Position.xyz;
    vec3 p2 = gl_in[2].gl_Position.xyz;
    vec3 faceNormal = normalize(cross(p1 - p0, p2 - p0));
    emitLine((p0 + p1 + p2) / 3.0, faceNormal, vec3(0.0, 1.0, 1.0));
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
