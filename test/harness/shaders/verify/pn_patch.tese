// PN-triangle evaluation with per-patch control points (patch inputs from the control stage),
// given alone: verify synthesizes the vertex and tessellation-control stages in front of it.
#version 450
layout (triangles, fractional_odd_spacing, ccw) in;

layout (set = 0, binding = 0) uniform UBO {
	mat4 projection;
	mat4 model;
	float tessAlpha;
} ubo;

layout (location = 0) in vec3 iNormal[];
layout (location = 1) in vec2 iUV[];
layout (location = 2) patch in vec3 b210;
layout (location = 3) patch in vec3 b120;
layout (location = 4) patch in vec3 b111;

layout (location = 0) out vec3 oNormal;
layout (location = 1) out vec2 oUV;

void main() {
	vec3 uvw = gl_TessCoord;
	oNormal = iNormal[0] * uvw.z + iNormal[1] * uvw.x + iNormal[2] * uvw.y;
	oUV = iUV[0] * uvw.z + iUV[1] * uvw.x + iUV[2] * uvw.y;
	vec3 flat_ = gl_in[0].gl_Position.xyz * uvw.z + gl_in[1].gl_Position.xyz * uvw.x + gl_in[2].gl_Position.xyz * uvw.y;
	vec3 pn = flat_ + (b210 * uvw.z * uvw.x + b120 * uvw.x * uvw.y) * 0.1 + b111 * uvw.x * uvw.y * uvw.z;
	vec3 pos = mix(flat_, pn, ubo.tessAlpha);
	gl_Position = ubo.projection * ubo.model * vec4(pos, 1.0);
}
