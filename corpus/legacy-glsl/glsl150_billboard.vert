#version 150
// stereoshift-expect: intermediate
// GLSL 1.50 point-sprite pipeline vertex stage: passes the view-space centre on to the geometry shader.
in vec3 center;

uniform mat4 modelView;

out vec4 viewCenter;

void main()
{
    viewCenter = modelView * vec4(center, 1.0);
    gl_Position = viewCenter;
}
