#version 450
#extension GL_AMD_vertex_shader_layer : require
// Vulkan GLSL glslang refuses (an extension it does not know): glslang is Vulkan GLSL's reference
// compiler and OpenGL's compilers cannot read it (descriptor sets), so no second compiler can vouch
// for it: the text-only route is refused with glslang's errors and a note that says why (before
// Mesa's check: converted from the text; with it, Mesa's misleading "unrecognized layout identifier
// `set'"). --unchecked-text-route takes it, said in the report.
// RUN: %not %stereoshift %s -o %t.vert 2>&1 | FileCheck %s
// RUN: %not test -e %t.vert
// RUN: %stereoshift %s --unchecked-text-route -o %t.unchecked.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=UNCHECKED
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: error: '#extension' : extension not supported: GL_AMD_vertex_shader_layer
// CHECK-NOT: Mesa: unrecognized
// CHECK: note: the text-only route is taken only where Mesa's GLSL compiler compiles the shader, and none could be asked (the shader is Vulkan GLSL, which only glslang, its reference compiler, reads; no OpenGL compiler can vouch for it)
// UNCHECKED: warning: no GLSL compiler checked this shader, which glslang refuses (the shader is Vulkan GLSL
// REPORT: "original": "unchecked: the shader is Vulkan GLSL
// REPORT: "route": "glsl-text-only"
layout(location = 0) in vec4 position;
layout(set = 0, binding = 0) uniform Camera { mat4 mvp; } cam;
void main()
{
    gl_Layer = 1;
    gl_Position = cam.mvp * position;
}
