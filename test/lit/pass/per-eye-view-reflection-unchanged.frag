// per-eye-view: an environment map sampled along reflect(-V, N) is a lookup, not a texture
// coordinate moved along V: mono by default, the shader is copied.
// RUN: %stereoshift --validate-each %s -o %t.frag --report %t.json
// RUN: cmp %s %t.frag
// RUN: FileCheck %s --input-file %t.json
// CHECK: "use": "texture looked up along a direction from it (reflection, BRDF table), no texture coordinate moved along it"
// CHECK: "result": "unchanged"
#version 450
layout(set = 0, binding = 0) uniform Frame { vec4 eyePosition; } frame;
layout(set = 0, binding = 1) uniform samplerCube skyMap;
layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 V = normalize(frame.eyePosition.xyz - inWorld);
  outColor = texture(skyMap, reflect(-V, normalize(inNormal)));
}
