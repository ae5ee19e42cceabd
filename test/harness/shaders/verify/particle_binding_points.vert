// OpenGL 4.3 particle vertex shader: positions from a shader storage block, a colour ramp texture,
// the camera in a uniform block, a loose point-size uniform. Uniform block 0, storage block 0 and
// texture unit 0 are three different binding points in OpenGL.
#version 430 core
layout(std140, binding = 0) uniform Camera {
    mat4 viewProjection;
};
layout(std430, binding = 0) readonly buffer Particles {
    vec4 particles[];  // xyz position, w age in [0, 1]
};
layout(binding = 0) uniform sampler2D colorRamp;
uniform float pointScale;

out vec4 vColor;

void main()
{
    vec4 p = particles[gl_VertexID % 64];
    vColor = textureLod(colorRamp, vec2(p.w, 0.5), 0.0);
    gl_PointSize = pointScale * (1.0 - p.w);
    gl_Position = viewProjection * vec4(p.xyz, 1.0);
}
