#version 450
// stereoshift-expect: deferred-unproject
// Vulkan tiled-light style shading: the view ray of each pixel made in the fragment shader from
// gl_FragCoord through the inverse projection (the pixel's far-plane point), scaled so that its z
// is the linear view depth stored in the G-buffer.

layout(set = 0, binding = 0) uniform View {
    mat4 invProjection;
    vec4 screenSize;        // xy pixels, zw 1 / pixels
    vec4 lightPosRadius;    // view space
    vec4 lightColor;
} view;

layout(set = 0, binding = 1) uniform sampler2D linearDepthBuffer;   // positive view depth
layout(set = 0, binding = 2) uniform sampler2D normalBuffer;

layout(location = 0) out vec4 outColor;

/* ---- stereoshift ---- */ vec3 stereoshift_view_ray_viewPos(vec3 stereoshift_p); /* ---- end stereoshift ---- */ void main()
{
    vec2 uv = gl_FragCoord.xy * view.screenSize.zw;
    vec4 farPlane = view.invProjection * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 viewRay = farPlane.xyz / farPlane.w;
    float viewDepth = texture(linearDepthBuffer, uv).r;
    vec3 viewPos = stereoshift_view_ray_viewPos(viewRay * (viewDepth / -viewRay.z));

    vec3 n = normalize(texture(normalBuffer, uv).xyz * 2.0 - 1.0);
    vec3 toLight = view.lightPosRadius.xyz - viewPos;
    float dist = length(toLight);
    float atten = clamp(1.0 - dist / view.lightPosRadius.w, 0.0, 1.0);
    outColor = vec4(view.lightColor.rgb * max(dot(n, toLight / dist), 0.0) * atten * atten, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
layout(set = 0, binding = 3, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec3 stereoshift_view_ray_viewPos(vec3 stereoshift_p)
{
    if (stereo.eyeSign != 0.0)
        stereoshift_p.x = stereoshift_p.x - ((stereo.eyeSign * stereo.separation) * (abs(stereoshift_p.z) - stereo.convergence)) * view.invProjection[0][0];
    return stereoshift_p;
}
// ---- end stereoshift ----
