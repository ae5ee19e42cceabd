#version 450
// A per-draw push-constant block (model matrix, a scale) the eye parameters join when converted
// with --eye-source push-constant.
layout(set = 0, binding = 0) uniform Frame {
    mat4 viewProjection;
} frame;
layout(push_constant) uniform Draw {
    mat4 model;
    float scale;
} draw;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUV;
layout(location = 0) out vec2 outUV;
layout(location = 1) out vec4 outClip;
void main()
{
    outUV = inUV;
    gl_Position = frame.viewProjection * draw.model * vec4(inPosition * draw.scale, 1.0);
    outClip = gl_Position;
}
