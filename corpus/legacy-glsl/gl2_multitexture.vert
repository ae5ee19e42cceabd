#version 120
// stereoshift-expect: shift
// GL 2.1 tutorial multitexturing vertex shader: gl_MultiTexCoord0/1 through gl_TextureMatrix into gl_TexCoord[], gl_FrontColor.
void main()
{
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_MultiTexCoord1;
    gl_FrontColor = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
