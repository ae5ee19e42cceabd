#version 330 core
// stereoshift-expect: 2d
// OpenGL 3.3 deferred point light, vertex stage: a full-screen quad whose four corners carry the
// view-space frustum-corner rays (z = -1) from a uniform array, indexed by gl_VertexID.

uniform vec3 frustumRays[4];

layout(location = 0) in vec2 aPos;
out vec2 TexCoords;
out vec3 ViewRay;

void main()
{
    TexCoords = aPos * 0.5 + 0.5;
    ViewRay = frustumRays[gl_VertexID];
    gl_Position = vec4(aPos, 0.0, 1.0);
}
