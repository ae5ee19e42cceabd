#version 330
// stereoshift-expect: fragment
// Normal-visualisation fragment shader: flat line colour with a global debug opacity.

in vec3 gColor;

uniform float uOpacity;
uniform float uHighlight;   // 0 or 1

out vec4 fragColor;

void main()
{
    vec3 color = gColor;
    if (uHighlight > 0.5)
        color = mix(color, vec3(1.0, 0.0, 1.0), 0.5);
    // Keep lines visible on both dark and bright backgrounds.
    color = max(color, vec3(0.05));
    fragColor = vec4(color, uOpacity);
}
