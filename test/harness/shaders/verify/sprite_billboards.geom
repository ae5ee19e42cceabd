// Vulkan GLSL billboards: world-space points expanded to camera-facing quads with the camera's
// right and up vectors from the view matrix, projection and view in a uniform block.
#version 450
layout (points) in;
layout (triangle_strip, max_vertices = 4) out;

layout (set = 0, binding = 0) uniform Scene
{
	mat4 projection;
	mat4 view;
	float spriteSize;
} scene;

layout (location = 0) in vec4 inColor[];
layout (location = 0) out vec4 outColor;
layout (location = 1) out vec2 outUV;

void main()
{
	vec3 right = vec3(scene.view[0][0], scene.view[1][0], scene.view[2][0]);
	vec3 up = vec3(scene.view[0][1], scene.view[1][1], scene.view[2][1]);
	vec3 center = gl_in[0].gl_Position.xyz;
	for (int i = 0; i < 4; ++i) {
		vec2 corner = vec2(i & 1, i >> 1) * 2.0 - 1.0;
		vec3 world = center + (right * corner.x + up * corner.y) * scene.spriteSize;
		outColor = inColor[0];
		outUV = corner * 0.5 + 0.5;
		gl_Position = scene.projection * scene.view * vec4(world, 1.0);
		EmitVertex();
	}
	EndPrimitive();
}
