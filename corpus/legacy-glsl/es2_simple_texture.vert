#version 100
// stereoshift-expect: shift
// GL ES 2.0 SDK style vertex shader: a_/u_/v_ naming, one MVP matrix, texture coordinates passed on.
uniform mat4 u_mvpMatrix;

attribute vec4 a_position;
attribute vec2 a_texCoord;

varying vec2 v_texCoord;

void main()
{
    gl_Position = u_mvpMatrix * a_position;
    v_texCoord = a_texCoord;
}
