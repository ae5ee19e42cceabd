#version 450
// stereoshift-expect: shift
// Vulkan world-anchored HUD label vertex shader: screen-space quad pushed to the anchor's eye depth with vec4(p.xy*d, z, d).

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 view;
    mat4 proj;
    vec4 viewportSize;
} camera;

layout(push_constant) uniform LabelPush {
    vec4 anchorWorld;   // xyz world anchor
    vec2 pixelSize;     // label size in pixels
    vec2 pixelOffset;   // offset from the anchor in pixels
} label;

layout(location = 0) in vec2 inCorner;   // [0,1]^2
layout(location = 0) out vec2 outUV;

void main_stereoshift_mono()
{
    vec4 anchorClip = camera.proj * camera.view * vec4(label.anchorWorld.xyz, 1.0);
    float d = max(anchorClip.w, 0.01);
    float z = anchorClip.z / d;
    vec2 anchorNdc = anchorClip.xy / d;

    vec2 px = label.pixelOffset + (inCorner - vec2(0.5, 0.0)) * label.pixelSize;
    vec2 p = anchorNdc + px * 2.0 / camera.viewportSize.xy;
    outUV = vec2(inCorner.x, 1.0 - inCorner.y);
    gl_Position = vec4(p.xy * d, z * d, d);
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
void main()
{
    main_stereoshift_mono();
    if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
        gl_Position.x = stereoshift_x;
    }
}
// ---- end stereoshift ----
