// --eye-source multiview for OpenGL (a LearnOpenGL-style 330 shader with loose uniforms):
// GL_OVR_multiview2 with `layout(num_views = 2) in;`, eyeSign from gl_ViewID_OVR, separation and
// convergence loose uniforms like the shader's own. SPIRV-Cross writes gl_ViewID_OVR in vertex
// shaders only, so the view is handed on to the fragment stage as the flat varying stereoEye.
// RUN: %stereoshift --eye-source multiview --verify %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift --eye-source multiview --multiview-params uniform-block %s -o - | FileCheck %s --check-prefix=BLOCK
#version 330 core
layout (location = 0) in vec3 aPos;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
void main()
{
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
// CHECK: #version 330
// CHECK-NEXT: #extension GL_OVR_multiview2 : require
// CHECK-NEXT: layout(num_views = 2) in;
// CHECK: uniform float separation;
// CHECK: flat out int stereoEye;
// CHECK: stereoEye = int(gl_ViewID_OVR);
// CHECK: ((int(gl_ViewID_OVR) != 0) ? 1.0 : (-1.0))
// REPORT: "requires": "GL_OVR_multiview2 (plain GL_OVR_multiview lets only gl_Position depend on the view)"
// BLOCK: uniform StereoParams
