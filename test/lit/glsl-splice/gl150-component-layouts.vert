#version 150
#extension GL_ARB_separate_shader_objects : require
#extension GL_ARB_enhanced_layouts : require
// Two outputs packed into one location by components, allowed at 150 by the source's own
// extensions: the layouts and the #extension lines stay as written (a re-emission declares the
// extensions it thinks it needs and dropped `component`).
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s
// CHECK: #version 150
// CHECK-NEXT: #extension GL_ARB_separate_shader_objects : require
// CHECK-NEXT: #extension GL_ARB_enhanced_layouts : require
// CHECK: layout(location = 0, component = 0) out float vFog;
// CHECK-NEXT: layout(location = 0, component = 1) out float vHeight;
// CHECK: uniform float eyeSign;
// CHECK: main_stereoshift_mono();
in vec4 position;
uniform mat4 mvp;
layout(location = 0, component = 0) out float vFog;
layout(location = 0, component = 1) out float vHeight;
void main()
{
    gl_Position = mvp * position;
    vFog = clamp(gl_Position.z / 100.0, 0.0, 1.0);
    vHeight = position.y;
}
