#version 450
// Vulkan GLSL: the eye parameters as each eye source declares them, spelled in the text the way
// the passes declared them in the IR (set, binding, spec ids, push-constant block), and read by
// the shift through the block's instance name.
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s --check-prefix=BLOCK
// RUN: %stereoshift --set 2 --binding 5 --instance-name eye %s -o - | %rmchecks | FileCheck %s --check-prefix=BOUND
// RUN: %stereoshift --eye-source push-constant %s -o - | %rmchecks | FileCheck %s --check-prefix=PUSH
// RUN: %stereoshift --eye-source spec-constant --spec-id-base 40 %s -o - | %rmchecks | FileCheck %s --check-prefix=SPEC
// BLOCK: layout(set = 0, binding = 1, std140) uniform StereoParams
// BLOCK-NEXT: {
// BLOCK-NEXT:     float eyeSign;
// BLOCK-NEXT:     float separation;
// BLOCK-NEXT:     float convergence;
// BLOCK-NEXT: } stereo;
// BLOCK: precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
// BOUND: layout(set = 2, binding = 5, std140) uniform StereoParams
// BOUND: } eye;
// BOUND: if (eye.eyeSign != 0.0
// PUSH: layout(push_constant) uniform StereoParams
// PUSH: (stereo.eyeSign * stereo.separation)
// SPEC: layout(constant_id = 40) const float eyeSign = 0.0;
// SPEC-NEXT: layout(constant_id = 41) const float separation = {{[0-9.e+-]+}};
// SPEC-NEXT: layout(constant_id = 42) const float convergence = {{[0-9.e+-]+}};
layout(location = 0) in vec3 inPosition;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProjection; } camera;
void main()
{
    gl_Position = camera.viewProjection * vec4(inPosition, 1.0);
}
