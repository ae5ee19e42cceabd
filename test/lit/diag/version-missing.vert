// A GLSL shader without #version is GLSL 110 (the report says why), never glslang's misleading
// "ES shaders for SPIR-V require version 310 or higher".
// RUN: %stereoshift %s -o %t.out --report %t.json 2>&1 | FileCheck %s --allow-empty --check-prefix=LOG
// RUN: FileCheck %s --input-file %t.json
// LOG-NOT: ES shaders
// CHECK: "dialect": "110"
// CHECK: "dialect_reason": "no #version and nothing ES-only, so GLSL's default 110"
void main() {
  gl_Position = vec4(0.0);
}
