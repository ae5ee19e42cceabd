#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform CameraUBO
{
    mat4 view;
    mat4 proj;
    vec4 viewportSize;
} camera;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(push_constant, std430) uniform LabelPush
{
    vec4 anchorWorld;
    vec2 pixelSize;
    vec2 pixelOffset;
} label;

layout(location = 0) in vec2 inCorner;
layout(location = 0) out vec2 outUV;

void main()
{
    vec4 anchorClip = (camera.proj * camera.view) * vec4(label.anchorWorld.xyz, 1.0);
    float d = max(anchorClip.w, 0.00999999977648258209228515625);
    float z = anchorClip.z / d;
    vec2 anchorNdc = anchorClip.xy / vec2(d);
    vec2 px = label.pixelOffset + ((inCorner - vec2(0.5, 0.0)) * label.pixelSize);
    vec2 p = anchorNdc + ((px * 2.0) / camera.viewportSize.xy);
    outUV = vec2(inCorner.x, 1.0 - inCorner.y);
    vec2 _103 = p * d;
    float _106 = z * d;
    float _108 = _103.x;
    float _109 = _103.y;
    vec4 _110 = vec4(_108, _109, _106, d);
    gl_Position = _110;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _141 = gl_Position.w - stereo.convergence;
        precise float _142 = stereo.eyeSign * stereo.separation;
        precise float _143 = _142 * _141;
        precise float _144 = gl_Position.x + _143;
        gl_Position.x = _144;
    }
}

