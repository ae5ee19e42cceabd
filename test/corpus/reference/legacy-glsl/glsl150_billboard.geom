#version 150
// stereoshift-expect: shift
// GLSL 1.50 billboard geometry shader: one point in, a camera-facing quad out, projected per corner.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform mat4 projection;
uniform float halfSize;

in vec4 viewCenter[];

out vec2 cornerUv;

/* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main()
{
    for (int i = 0; i < 4; ++i) {
        vec2 corner = vec2(float(i % 2), float(i / 2)) * 2.0 - 1.0;
        cornerUv = corner * 0.5 + 0.5;
        gl_Position = projection * (viewCenter[0] + vec4(corner * halfSize, 0.0, 0.0));
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
