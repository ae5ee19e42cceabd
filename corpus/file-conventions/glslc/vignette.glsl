#version 330
// stereoshift-expect: fragment
// glslc-style `.glsl` with `#pragma shader_stage(fragment)`: a vignette over the scene colour.
#pragma shader_stage(fragment)

in vec2 vUV;
out vec4 fragColor;
uniform sampler2D sceneColor;
uniform float strength;

void main()
{
    vec2 centred = vUV - 0.5;
    float fade = 1.0 - strength * dot(centred, centred);
    fragColor = vec4(texture(sceneColor, vUV).rgb * fade, 1.0);
}
