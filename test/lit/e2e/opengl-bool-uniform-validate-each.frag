// --validate-each blames a pass only for what it broke: the front end's module of a shader with a
// loose `uniform bool` already fails validation, and the per-eye-view pass that changes it is not
// reported for it.
// RUN: %stereoshift --validate-each --per-eye-specular %s -o %t.frag 2>&1 | FileCheck %s --allow-empty
// RUN: FileCheck %s --check-prefix=OUT < %t.frag
// CHECK-NOT: error
// OUT: uniform bool blinn;
#version 330 core
uniform bool blinn;
uniform vec3 lightPos;
uniform vec3 viewPos;
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
void main() {
  vec3 viewDir = normalize(viewPos - FragPos);
  vec3 lightDir = normalize(lightPos - FragPos);
  float spec = blinn ? pow(max(dot(Normal, normalize(lightDir + viewDir)), 0.0), 32.0)
                     : pow(max(dot(reflect(-lightDir, Normal), viewDir), 0.0), 8.0);
  FragColor = vec4(vec3(spec), 1.0);
}
