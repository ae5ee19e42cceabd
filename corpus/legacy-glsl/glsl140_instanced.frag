#version 140
// stereoshift-expect: fragment
// GLSL 1.40 instanced grid fragment shader: the shade from the vertex stage into its own output.
in float instanceShade;

out vec4 fragColor;

void main()
{
    fragColor = vec4(vec3(instanceShade), 1.0);
}
