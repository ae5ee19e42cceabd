#extension GL_AMD_vertex_shader_layer : require
// GLSL without #version (an engine or a test runner prepends the one it needs) that glslang cannot
// take: Mesa's GLSL compiler is asked at each version it has, from GLSL's default 110 up, and the
// first that takes the text decides (here 130: `in` at global scope needs it); the output is compiled
// at the same version. Before, Mesa was asked at 110 only and refused the route.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2>/dev/null
// RUN: FileCheck %s < %t.json
// CHECK: "mesa": {
// CHECK: "original": "compiled"
// CHECK: "output": "compiled"
// CHECK: "read_at": "130"
// CHECK: "route": "glsl-text-only"
in vec4 position;
uniform int layer;
void main()
{
    gl_Layer = layer;
    gl_Position = position;
}
