// --pass runs only the named passes (repeatable) and the passes they require, in the pipeline's own order.
// Detection alone changes nothing, so the GLSL input is copied byte for byte:
// RUN: %stereoshift %s --pass clip-position-detection -o %t.detect.vert
// RUN: cmp %s %t.detect.vert
// Detection + eye-params declares the block but injects no shift; with no shift for the source
// splice to append, SPIRV-Cross re-emits the module, and the report's notes say so:
// RUN: %stereoshift %s --verify --pass clip-position-detection --pass eye-params -o - --report %t.json | %rmchecks | FileCheck %s --check-prefix=DECLARE
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// The order on the command line does not matter:
// RUN: %stereoshift %s --verify --pass stereo-shift --pass eye-params --pass clip-position-detection -o - | %rmchecks | FileCheck %s --check-prefix=ALL
// stereo-shift alone pulls in the passes it requires (detection, eye-params) and shifts; the report
// says why they ran. It used to return the original shader:
// RUN: %stereoshift %s --verify --pass stereo-shift -o - --report %t.required.json | %rmchecks | FileCheck %s --check-prefix=ALL
// RUN: FileCheck %s --check-prefix=REQUIRED --input-file %t.required.json
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
// REPORT: "notes": [
// REPORT-NEXT: "GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the stage changed but its clip position is not shifted"
// REPORT-NEXT: ],
// REPORT-NOT: "halo"
// REPORT-NOT: "stereo-shift"
// REPORT: "passes": {
// REPORT-NEXT: "clip-position-detection": {
// REPORT: "eye-params": {
// REPORT: "result": "changed"
// REPORT-NOT: "halo"
// REPORT-NOT: "stereo-shift"
// ALL: uniform StereoParams
// ALL: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
// REQUIRED: "passes": {
// REQUIRED-NEXT: "clip-position-detection": {
// REQUIRED: "required_by": "stereo-shift",
// REQUIRED-NEXT: "result": "unchanged"
// REQUIRED: "eye-params": {
// REQUIRED: "required_by": "stereo-shift",
// REQUIRED-NEXT: "result": "changed"
// REQUIRED-NOT: "halo"
// REQUIRED: "stereo-shift": {
// REQUIRED-NOT: "required_by"
// REQUIRED: "result": "changed"
