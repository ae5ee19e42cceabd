// --target-version sets the output GLSL version: 460 from a 450 source; and a GL 330 source
// raised to 410 gains `precise` on the shift (GLSL 400+), which 330 cannot express.
// RUN: %stereoshift --verify --target-version 460 %s -o - | %rmchecks | FileCheck %s --check-prefix=V460
// RUN: %stereoshift --verify --target-version 410 %S/Inputs/gl330.vert -o - | %rmchecks | FileCheck %s --check-prefix=V410
// RUN: %stereoshift --verify %S/Inputs/gl330.vert -o - | %rmchecks | FileCheck %s --check-prefix=V330
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// V460: {{^}}#version 460{{$}}
// V460: uniform StereoParams
// V410: {{^}}#version 410{{$}}
// V410: precise float {{_[0-9]+}} = eyeSign * separation;
// V330: {{^}}#version 330{{$}}
// V330-NOT: precise
// Without --target-version the 330 source is spliced at its own version, the plain shift (no precise):
// V330: {{^ *}}gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
