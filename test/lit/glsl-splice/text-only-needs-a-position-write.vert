#version 150
#extension GL_ARB_gpu_shader5 : require
// The text-only shift never guesses: a shader glslang cannot take whose text writes no gl_Position
// of its own (here through a helper defined in another compilation unit: glslang refuses the unit
// at its link, Mesa compiles it alone) keeps glslang's error, exit 1, with a note saying why the
// text was not enough.
// RUN: %not %stereoshift %s -o %t.vert 2>&1 | FileCheck %s
// RUN: %not test -e %t.vert
// CHECK: error: Linking vertex stage: No function definition (body) found
// CHECK: note: no shift from the text alone either: the text writes no gl_Position of its own
in vec4 position;
void write(vec4 p);
void main()
{
    write(position * 2.0);
}
