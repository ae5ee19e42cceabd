#version 330
// stereoshift-expect: 2d
// glslc-style `.glsl` with `#pragma shader_stage(vertex)`: a full-screen triangle from gl_VertexID, w = 1.
#pragma shader_stage(vertex)

out vec2 vUV;

void main()
{
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUV = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
