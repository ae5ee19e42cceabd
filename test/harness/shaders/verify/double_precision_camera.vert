// OpenGL 4.0 vertex shader for large worlds (planetary / GIS style): the model, view and projection
// matrices are loose dmat4 uniforms and the transform runs in double precision, with the camera
// position subtracted in double before the projection; the clip position is converted to vec4 at
// the end. The harness's default uniform block lays dmat4 / dvec3 out with std140's 8-byte
// scalars (32-byte dvec4 columns).
#version 400 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

uniform dmat4 model;
uniform dmat4 view;
uniform dmat4 projection;
uniform dvec3 cameraOrigin;
uniform mat3 normalMatrix;

out vec3 vNormal;
out vec3 vRelative;

void main()
{
    dvec4 world = model * dvec4(aPos, 1.0);
    dvec3 relative = world.xyz - cameraOrigin;
    vRelative = vec3(relative);
    vNormal = normalize(normalMatrix * aNormal);
    dvec4 clip = projection * (view * dvec4(relative, 1.0));
    gl_Position = vec4(clip);
}
