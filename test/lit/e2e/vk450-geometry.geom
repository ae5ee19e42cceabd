// A geometry shader is shifted before every EmitVertex: the one in main's loop and the one inside
// the called function emitOne(); EndPrimitive gets nothing.
// RUN: %stereoshift --verify %s --report %t.json -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// Each emit statement is wrapped with the shift of the vertex it emits; each function that emits
// gets the helper's prototype first.
// CHECK: /* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void emitOne(vec3 p) {
// CHECK-NEXT: gl_Position = camera.viewProj * vec4(p + vec3(0.0, 0.0, 1.0), 1.0);
// CHECK-NEXT: { stereoshift_shiftPosition(); EmitVertex(); }
// CHECK: /* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main() {
// CHECK-NEXT: for (int i = 0; i < 3; ++i) {
// CHECK-NEXT: gl_Position = camera.viewProj * vec4(inPos[i], 1.0);
// CHECK-NEXT: { stereoshift_shiftPosition(); EmitVertex(); }
// CHECK-NEXT: }
// CHECK-NEXT: EndPrimitive();
// CHECK-NOT: stereoshift_shiftPosition(); EmitVertex
// CHECK: emitOne(inPos[0]);
// CHECK-NEXT: emitOne(inPos[1]);
// CHECK-NEXT: emitOne(inPos[2]);
// CHECK-NEXT: EndPrimitive();
// CHECK: layout(set = 0, binding = 1, std140) uniform StereoParams
// CHECK: void stereoshift_shiftPosition()
// CHECK-NEXT: {
// CHECK-NEXT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPos[];

void emitOne(vec3 p) {
  gl_Position = camera.viewProj * vec4(p + vec3(0.0, 0.0, 1.0), 1.0);
  EmitVertex();
}

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = camera.viewProj * vec4(inPos[i], 1.0);
    EmitVertex();
  }
  EndPrimitive();
  emitOne(inPos[0]);
  emitOne(inPos[1]);
  emitOne(inPos[2]);
  EndPrimitive();
}

// REPORT: "stereo-shift": {
// REPORT-NEXT: "form": "branch",
// REPORT-NEXT: "result": "changed",
// REPORT-NEXT: "sites": 2
// REPORT: "stage": "geom",
