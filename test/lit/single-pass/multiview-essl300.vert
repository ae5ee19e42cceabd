#version 300 es
// --eye-source multiview for OpenGL ES 3.0 (an SDK-style shader): GL_OVR_multiview2 in ESSL 300.
// RUN: %stereoshift --eye-source multiview --verify %s -o %t.vert
// RUN: %rmchecks %t.vert | FileCheck %s
in vec4 a_position;
in vec2 a_texCoord;
uniform mat4 u_mvpMatrix;
out vec2 v_texCoord;
void main()
{
    gl_Position = u_mvpMatrix * a_position;
    v_texCoord = a_texCoord;
}
// CHECK: #version 300 es
// CHECK-NEXT: #extension GL_OVR_multiview2 : require
// CHECK-NEXT: layout(num_views = 2) in;
// CHECK: (int(gl_ViewID_OVR) != 0) ? 1.0 : (-1.0)
