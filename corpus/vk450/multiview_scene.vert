#version 450
// stereoshift-expect: already-stereo
// Single-pass stereo (VK_KHR_multiview): one draw renders both eyes, each view picks its own
// projection and view matrix by gl_ViewIndex. Already stereo: copied, never shifted a second time.
#extension GL_EXT_multiview : enable

layout(set = 0, binding = 0) uniform SceneMatrices {
  mat4 projection[2];
  mat4 view[2];
  vec4 lightPos;
} scene;

layout(push_constant) uniform PushConsts {
  mat4 model;
} primitive;

layout(location = 0) in vec3 inPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUV;
layout(location = 2) out vec3 outLightVec;
layout(location = 3) out vec3 outViewVec;

void main() {
  vec4 worldPos = primitive.model * vec4(inPos, 1.0);
  vec4 viewPos = scene.view[gl_ViewIndex] * worldPos;
  outNormal = mat3(scene.view[gl_ViewIndex] * primitive.model) * inNormal;
  outUV = inUV;
  outLightVec = (scene.view[gl_ViewIndex] * scene.lightPos).xyz - viewPos.xyz;
  outViewVec = -viewPos.xyz;
  gl_Position = scene.projection[gl_ViewIndex] * viewPos;
}
