#version 150
#extension GL_ARB_gpu_shader5 : require
// The text-only shift never guesses: a shader glslang cannot parse whose text writes no
// gl_Position of its own (here through a helper in an #include-free macro glslang rejects) keeps
// glslang's error, exit 1, with a note saying why the text was not enough.
// RUN: %not %stereoshift %s -o %t.vert 2>&1 | FileCheck %s
// RUN: %not test -e %t.vert
// CHECK: error:
// CHECK: note: no shift from the text alone either: the text writes no gl_Position of its own
in vec4 position;
void write(vec4 p);
void main()
{
    write(position * notDeclaredAnywhere);
}
