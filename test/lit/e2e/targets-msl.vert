// --target msl emits Metal with the eye parameters and the guarded shift.
// RUN: %stereoshift --target msl %s -o - | %rmchecks | FileCheck %s --check-prefix=MSL
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// MSL: struct StereoParams
// MSL-NEXT: {
// MSL-NEXT: float eyeSign;
// MSL-NEXT: float separation;
// MSL-NEXT: float convergence;
// MSL-NEXT: };
// MSL: float4 gl_Position {{\[\[position(, invariant)?\]\]}};
// MSL: vertex main0_out main0(
// MSL: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(out.gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(out.gl_Position.w))))
// MSL: stereo.eyeSign * stereo.separation
