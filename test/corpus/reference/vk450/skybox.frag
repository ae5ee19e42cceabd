#version 450
// stereoshift-expect: fragment
// Vulkan skybox fragment shader: HDR cube map with an analytic sun disc.

layout(set = 0, binding = 1) uniform samplerCube skyCube;

layout(set = 0, binding = 2) uniform SunUBO {
    vec4 sunDirection;   // xyz normalised, w angular radius cosine
    vec4 sunColor;
} sun;

layout(location = 0) in vec3 inDirection;

layout(location = 0) out vec4 outColor;

void main()
{
    vec3 dir = normalize(inDirection);
    vec3 color = texture(skyCube, dir).rgb;
    float cosAngle = dot(dir, sun.sunDirection.xyz);
    float disc = smoothstep(sun.sunDirection.w, sun.sunDirection.w + 0.0005, cosAngle);
    color += sun.sunColor.rgb * disc;
    outColor = vec4(color, 1.0);
}
