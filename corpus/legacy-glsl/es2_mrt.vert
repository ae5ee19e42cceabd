#version 100
// stereoshift-expect: shift
// GL ES 2.0 SDK style multiple-render-target vertex shader: position, normal and a world-space position varying.
uniform mat4 u_mvpMatrix;
uniform mat4 u_modelMatrix;

attribute vec4 a_position;
attribute vec3 a_normal;

varying vec3 v_normal;
varying vec3 v_worldPos;

void main()
{
    v_normal = mat3(u_modelMatrix) * a_normal;
    v_worldPos = (u_modelMatrix * a_position).xyz;
    gl_Position = u_mvpMatrix * a_position;
}
