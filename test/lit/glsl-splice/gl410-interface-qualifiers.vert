#version 410
// Interpolation qualifiers, a redeclared gl_PerVertex block and an interface block stay as written
// (a re-emission respells them); the eye parameters, asked for as loose uniforms, are OpenGL's
// default-block uniforms even though this #version 410 shader has no uniforms of its own that
// would say it is OpenGL GLSL rather than Vulkan GLSL.
// RUN: %stereoshift --eye-source loose-uniforms %s -o - | %rmchecks | FileCheck %s
// CHECK: out gl_PerVertex { vec4 gl_Position; float gl_PointSize; };
// CHECK-NEXT: out VertexData {
// CHECK-NEXT:     noperspective vec2 screenUv;
// CHECK-NEXT:     flat int layer;
// CHECK-NEXT:     centroid vec3 colour;
// CHECK-NEXT: } vs_out;
// CHECK: uniform float eyeSign;
// CHECK-NEXT: uniform float separation;
// CHECK-NEXT: uniform float convergence;
// CHECK: precise float stereoshift_x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NEXT: gl_Position.x = stereoshift_x;
in vec4 corner;
out gl_PerVertex { vec4 gl_Position; float gl_PointSize; };
out VertexData {
    noperspective vec2 screenUv;
    flat int layer;
    centroid vec3 colour;
} vs_out;
void main()
{
    vs_out.screenUv = corner.xy;
    vs_out.layer = gl_InstanceID;
    vs_out.colour = vec3(corner.zw, 1.0);
    gl_Position = vec4(corner.xy * 4.0, 1.0, 4.0);
    gl_PointSize = 1.0;
}
