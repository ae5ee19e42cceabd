// Push constants larger than a device's limit (everything a draw needs in one block, as some
// samples do on desktop drivers with 256-byte limits and more): verify binds them as a buffer.
#version 450
layout (push_constant) uniform PushConsts {
	mat4 projection;
	mat4 view;
	mat4 model;
	mat4 lightSpace[4];
	vec4 tint[4];
	float time;
} push;

layout (location = 0) in vec3 inPos;
layout (location = 0) out vec4 outShadow;
layout (location = 1) out vec4 outTint;

void main() {
	outShadow = push.lightSpace[3] * push.model * vec4(inPos, 1.0);
	outTint = push.tint[2] * push.time;
	gl_Position = push.projection * push.view * push.model * vec4(inPos, 1.0);
}
