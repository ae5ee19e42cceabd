#version 450
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vDirection;
layout(push_constant) uniform Sky { mat4 viewProjectionNoTranslation; } sky;

void main() {
    vDirection = inPosition;
    gl_Position = (sky.viewProjectionNoTranslation * vec4(inPosition, 1.0)).xyww;
}
