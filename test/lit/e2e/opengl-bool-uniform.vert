// OpenGL tutorials switch features with a loose `uniform bool`. glslang's SPIR-V for it (a Bool
// variable in UniformConstant storage) is refused by the validator whatever the passes do: the shader
// converts, the report says what the front end's module already had, and only a SPIR-V output of it
// is refused, with the reason.
// RUN: %stereoshift --verify %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s --check-prefix=OUT
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// RUN: %not %stereoshift %s --target spirv -o %t.spv 2>&1 | FileCheck %s --check-prefix=SPIRV
// RUN: test ! -e %t.spv
// OUT: {{^}}uniform bool useTint;
// OUT: tint = useTint ? vec3(1.0, 0.5, 0.5) : vec3(1.0);
// OUT: {{^}}uniform float eyeSign;
// OUT: main_stereoshift_mono();
// OUT-NEXT: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
// OUT: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT: "front_end_spirv_invalid": "If OpTypeBool is stored in conjunction with OpVariable
// SPIRV: opengl-bool-uniform.vert: error: glslang's SPIR-V for this shader does not validate (If OpTypeBool
// SPIRV: it cannot be written as SPIR-V (choose a source-language --target)
#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform bool useTint;
out vec3 tint;
void main() {
  tint = useTint ? vec3(1.0, 0.5, 0.5) : vec3(1.0);
  gl_Position = projection * view * model * vec4(aPos, 1.0);
}
