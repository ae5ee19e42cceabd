// Metal has no geometry stage: a geometry shader to --target msl is refused with the reason and
// nothing is written (SPIRV-Cross used to give a function qualified `unknown`, which is not Metal).
// RUN: rm -f %t.metal
// RUN: %not %stereoshift %s --target msl -o %t.metal 2>&1 | FileCheck %s
// RUN: test ! -e %t.metal
// CHECK: targets-msl-geometry-refused.geom: error: --target msl: Metal has no geometry shader that SPIRV-Cross can write
// CHECK: 1 error generated.
#version 450
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
void main() {
  for (int i = 0; i < 4; ++i) {
    vec2 corner = vec2(i & 1, i >> 1) - 0.5;
    gl_Position = camera.viewProj * (gl_in[0].gl_Position + vec4(corner, 0.0, 0.0));
    EmitVertex();
  }
  EndPrimitive();
}
