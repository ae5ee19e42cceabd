#version 330
// stereoshift-expect: intermediate
// Normal-visualisation vertex shader: passes world-space position and normal on to the geometry shader.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out VertexData {
    vec3 normal;
} vsOut;

void main()
{
    vsOut.normal = normalize(uNormalMatrix * aNormal);
    gl_Position = uModel * vec4(aPosition, 1.0);
}
