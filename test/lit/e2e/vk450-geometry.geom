// A geometry shader is shifted before every EmitVertex: the one in main's loop and the one inside
// the called function emitOne(); EndPrimitive gets nothing.
// RUN: %stereoshift --verify %s --report %t.json -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPos[];
// CHECK: layout(set = 0, binding = 1, std140) uniform StereoParams

void emitOne(vec3 p) {
  gl_Position = camera.viewProj * vec4(p + vec3(0.0, 0.0, 1.0), 1.0);
  EmitVertex();
}
// CHECK: void emitOne(vec3 p)
// CHECK: gl_Position =
// CHECK-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(gl_Position.w))))
// CHECK-NEXT: {
// CHECK: gl_Position.x =
// CHECK-NEXT: }
// CHECK-NEXT: EmitVertex();
// CHECK-NEXT: }

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = camera.viewProj * vec4(inPos[i], 1.0);
    EmitVertex();
  }
  EndPrimitive();
// CHECK: void main()
// CHECK: for (int i = 0; i < 3; i++)
// CHECK: gl_Position =
// CHECK-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(gl_Position.w))))
// CHECK-NEXT: {
// CHECK: gl_Position.x =
// CHECK-NEXT: }
// CHECK-NEXT: EmitVertex();
// CHECK-NEXT: }
// CHECK-NEXT: EndPrimitive();
  emitOne(inPos[0]);
  emitOne(inPos[1]);
  emitOne(inPos[2]);
  EndPrimitive();
// CHECK-NOT: stereo.eyeSign
// CHECK: emitOne(
// CHECK-NOT: stereo.eyeSign
// CHECK: EndPrimitive();
// CHECK-NEXT: }
}

// REPORT: "stereo-shift": {
// REPORT-NEXT: "form": "branch",
// REPORT-NEXT: "result": "changed",
// REPORT-NEXT: "sites": 2
// REPORT: "stage": "geom",
