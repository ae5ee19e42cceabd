#version 150
// A GLSL 150 geometry shader: the shift at every EmitVertex needs the IR, so it is re-emitted by
// SPIRV-Cross at version 150 (the text route is for vertex shaders).
// RUN: %stereoshift %s --verify -o - | FileCheck %s
// CHECK: #version 150
// CHECK: uniform float eyeSign;
// CHECK: gl_Position.x =
// CHECK: EmitVertex();
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
uniform mat4 viewProjection;
in vec3 worldPosition[];
void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = viewProjection * vec4(worldPosition[i], 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
