#version 450
// stereoshift-expect: fragment
// Billboard particle fragment shader: flipbook sprite sampled from an array texture, additive blend output.

layout(set = 1, binding = 0) uniform sampler2DArray spriteFrames;

layout(push_constant) uniform ParticlePush {
    float frame;
    float brightness;
} push;

layout(location = 0) in vec4 inColor;
layout(location = 1) in vec2 inUV;

layout(location = 0) out vec4 outColor;

void main()
{
    vec4 sprite = texture(spriteFrames, vec3(inUV, floor(push.frame)));
    vec4 next = texture(spriteFrames, vec3(inUV, floor(push.frame) + 1.0));
    vec4 blended = mix(sprite, next, fract(push.frame));
    float alpha = blended.a * inColor.a;
    outColor = vec4(blended.rgb * inColor.rgb * push.brightness * alpha, 0.0);
}
