#version 110
// stereoshift-expect: shift
// GL 2.x tutorial per-pixel Phong vertex shader: gl_NormalMatrix, gl_ModelViewMatrix, gl_Vertex and ftransform().
varying vec3 normal;
varying vec3 eyePosition;

void main()
{
    normal = normalize(gl_NormalMatrix * gl_Normal);
    eyePosition = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_Position = ftransform();
}
