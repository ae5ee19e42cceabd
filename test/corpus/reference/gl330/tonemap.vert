#version 330
// stereoshift-expect: 2d
// Full-screen post-process vertex shader: one oversized triangle generated from gl_VertexID, w = 1.0.

// Drawn with glDrawArrays(GL_TRIANGLES, 0, 3) and an empty vertex array object.
out vec2 vUV;

void main()
{
    // Vertex 0 -> (0,0), 1 -> (2,0), 2 -> (0,2) in UV space:
    // the triangle covers the whole viewport and the excess is clipped.
    vec2 uv = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUV = uv;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
