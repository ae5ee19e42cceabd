#version 120
// stereoshift-expect: shift
// GL 2.1 tutorial shadow-mapping vertex shader: the light's texture matrix on gl_TextureMatrix[7], ftransform().
varying vec4 shadowCoord;
varying vec3 normal;

void main()
{
    shadowCoord = gl_TextureMatrix[7] * gl_Vertex;
    normal = gl_NormalMatrix * gl_Normal;
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
}
