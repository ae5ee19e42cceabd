// per-eye-view: a reflection lookup (a cube map sampled along reflect(-v, n)) is a view vector used
// as a texture coordinate: per eye, like relief mapping (docs/stereo-math.md section 3: reflections should
// use the stereo eyes).
// RUN: %stereoshift --validate-each --verify %s -o %t.out.frag --report %t.json
// RUN: %rmchecks %t.out.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Scene { vec3 cameraPos; } scene;
layout(set = 0, binding = 1) uniform samplerCube environment;
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 v = scene.cameraPos - inWorldPos;
// CHECK: vec3 v = (scene.cameraPos + vec3(stereo.eyeOffsetX, stereo.eyeOffsetY, stereo.eyeOffsetZ)) - inWorldPos;
  outColor = texture(environment, reflect(-v, normalize(inNormal)));
}
// REPORT: "uniform": "scene.cameraPos",
// REPORT-NEXT: "why": "structure: a direction from it offsets texture coordinates in this stage (the name agrees)"
// REPORT: "result": "changed"
