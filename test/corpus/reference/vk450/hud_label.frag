#version 450
// stereoshift-expect: fragment
// Vulkan HUD label fragment shader: pre-rendered label texture with a drop shadow.

layout(set = 1, binding = 0) uniform sampler2D labelTexture;

layout(set = 1, binding = 1) uniform LabelStyle {
    vec4 textColor;
    vec4 shadowColor;
    vec2 shadowOffsetUV;
} style;

layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;

void main()
{
    float text = texture(labelTexture, inUV).r;
    float shadowMask = texture(labelTexture, inUV - style.shadowOffsetUV).r;
    vec4 color = style.shadowColor * shadowMask * (1.0 - text);
    color += style.textColor * text;
    if (color.a < 0.01)
        discard;
    outColor = color;
}
