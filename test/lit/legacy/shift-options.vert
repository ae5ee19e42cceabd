#version 100
// --shift-form select, --no-cutoff and --cutoff-epsilon are honoured by the text route.
// RUN: %stereoshift %s --shift-form select -o - | %rmchecks | FileCheck %s --check-prefix=SELECT
// RUN: %stereoshift %s --no-cutoff -o - | %rmchecks | FileCheck %s --check-prefix=NOCUT
// RUN: %stereoshift %s --cutoff-epsilon 0.25 -o - | %rmchecks | FileCheck %s --check-prefix=EPS
// SELECT: gl_Position.x = (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && abs(gl_Position.w) <= 3.40282347e+38) ? gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence) : gl_Position.x;
// NOCUT: if (eyeSign != 0.0)
// EPS: abs(gl_Position.w - 1.0) > 0.25 &&
attribute vec4 aPosition;
uniform mat4 uMatrix;
void main() {
  gl_Position = uMatrix * aPosition;
}
