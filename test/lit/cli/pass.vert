// --pass runs only the named passes (repeatable), in the pipeline's own order.
// Detection alone changes nothing, so the GLSL input is copied byte for byte:
// RUN: %stereoshift %s --pass clip-position-detection -o %t.detect.vert
// RUN: cmp %s %t.detect.vert
// Detection + eye-params declares the block but injects no shift:
// RUN: %stereoshift %s --verify --pass clip-position-detection --pass eye-params -o - --report %t.json | %rmchecks | FileCheck %s --check-prefix=DECLARE
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// The order on the command line does not matter:
// RUN: %stereoshift %s --verify --pass stereo-shift --pass eye-params --pass clip-position-detection -o - | %rmchecks | FileCheck %s --check-prefix=ALL
// stereo-shift without eye-params has nothing to read the parameters from:
// RUN: %not %stereoshift %s --pass clip-position-detection --pass stereo-shift -o %t.out 2>&1 | FileCheck %s --check-prefix=NEEDS
// RUN: test ! -e %t.out
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// DECLARE: uniform StereoParams
// DECLARE-NOT: invariant
// DECLARE: void main()
// DECLARE-NOT: if (
// DECLARE-NOT: eyeSign
// DECLARE: }
// REPORT-NOT: "halo"
// REPORT-NOT: "stereo-shift"
// REPORT: "passes": {
// REPORT-NEXT: "clip-position-detection": {
// REPORT: "eye-params": {
// REPORT: "result": "changed"
// REPORT-NOT: "halo"
// REPORT-NOT: "stereo-shift"
// ALL: uniform StereoParams
// ALL: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) >
// NEEDS: error: stereo-shift needs the eye-params pass to run first
// NEEDS: {{^}}1 error generated.
