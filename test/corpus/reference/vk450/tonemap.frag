#version 450
// stereoshift-expect: fragment
// Vulkan tonemap fragment shader: auto-exposure from a 1x1 luminance texture, Reinhard-extended curve.

layout(set = 0, binding = 0) uniform sampler2D hdrColor;
layout(set = 0, binding = 1) uniform sampler2D avgLuminance;

layout(push_constant) uniform TonemapPush {
    float keyValue;
    float whitePoint;
    float gamma;
} params;

layout(location = 0) in vec2 inUV;

layout(location = 0) out vec4 outColor;

void main()
{
    vec3 hdr = texture(hdrColor, inUV).rgb;
    float avg = max(texelFetch(avgLuminance, ivec2(0), 0).r, 1e-4);
    float lum = dot(hdr, vec3(0.2126, 0.7152, 0.0722));
    float scaled = lum * params.keyValue / avg;
    float mapped = scaled * (1.0 + scaled / (params.whitePoint * params.whitePoint)) / (1.0 + scaled);
    vec3 color = hdr * (mapped / max(lum, 1e-4));
    outColor = vec4(pow(color, vec3(1.0 / params.gamma)), 1.0);
}
