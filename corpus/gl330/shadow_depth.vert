#version 330
// stereoshift-expect: shift
// Shadow-map depth pass vertex shader using a light-space MVP (a mono pass: the draw, not the shader, decides).

layout(location = 0) in vec3 aPosition;
in vec2 aTexCoord;

uniform mat4 uLightMVP;
uniform float uDepthBias;

out vec2 vTexCoord;

void main()
{
    vTexCoord = aTexCoord;
    vec4 clip = uLightMVP * vec4(aPosition, 1.0);
    // Constant slope-free bias pushed into clip space.
    clip.z += uDepthBias * clip.w;
    gl_Position = clip;
}
