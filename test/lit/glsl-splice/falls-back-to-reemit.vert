#version 330
// What only the IR carries (here the HUD placed at depth: --hud-at-depth changes a 2D shader's
// position in the IR) is left to SPIRV-Cross's re-emit, with a note that says why; --force-reemit
// asks for the re-emit outright.
// RUN: %stereoshift --hud-at-depth %s -o - 2>&1 | %rmchecks | FileCheck %s
// RUN: %stereoshift --force-reemit %s -o - | %rmchecks | FileCheck %s --check-prefix=FORCED
// CHECK: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the splice cannot carry what the hud-at-depth pass changed
// CHECK-NOT: main_stereoshift_mono
// FORCED-NOT: main_stereoshift_mono
// FORCED: void main()
in vec2 corner;
uniform vec2 offset;
void main()
{
    gl_Position = vec4(corner + offset, 0.0, 1.0);
}
