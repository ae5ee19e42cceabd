// A Vulkan multiview shader picks its matrix by gl_ViewIndex: it is stereo already. It is classified
// already-stereo with the reason, copied byte for byte, and never shifted a second time.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: cmp %s %t.vert
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// NOTE: note: shader reads the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID): it is multiview stereo already; left as it is, never shifted twice
// REPORT: "classification": "already-stereo"
// REPORT: "output": "copied"
// REPORT: "already_stereo": "reads the view index
#version 450
#extension GL_EXT_multiview : require
layout(set = 0, binding = 0) uniform SceneUBO { mat4 projection[2]; mat4 view[2]; mat4 model; } ubo;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec3 outWorldPos;
void main() {
  vec4 world = ubo.model * vec4(inPos, 1.0);
  outWorldPos = world.xyz;
  gl_Position = ubo.projection[gl_ViewIndex] * ubo.view[gl_ViewIndex] * world;
}
