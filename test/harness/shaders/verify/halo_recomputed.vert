// Halo by value, Vulkan GLSL: a motion-blur / screen-space sample writes the clip position to its own
// varying by computing the product again (not by copying gl_Position), once inline and once through
// a helper. Both outputs are the position and must carry exactly its shifted x in each eye.
#version 450
layout(set = 0, binding = 0) uniform PerFrame { mat4 viewProj; } frame;
layout(push_constant) uniform PerObject { mat4 model; } object;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inTexCoord;

layout(location = 0) out vec2 outTexCoord;
layout(location = 1) out vec4 outClipPos;
layout(location = 2) out vec4 outClipPosHelper;

vec4 worldToClip(vec4 world) { return frame.viewProj * world; }

void main() {
    vec4 world = object.model * vec4(inPosition, 1.0);
    outTexCoord = inTexCoord;
    outClipPos = frame.viewProj * world;
    outClipPosHelper = worldToClip(object.model * vec4(inPosition, 1.0));
    gl_Position = frame.viewProj * world;
}
