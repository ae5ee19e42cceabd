// OpenGL 3.3 core vertex shader of a render-to-texture pass with a loose `uniform bool` toggle that
// flips the image (and its texture coordinates) vertically, the model / view / projection matrices
// as loose uniforms. glslang's SPIR-V for the bool does not validate; verify runs it all the same.
#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords;

out vec2 TexCoords;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform bool flipY;

void main()
{
    TexCoords = flipY ? vec2(aTexCoords.x, 1.0 - aTexCoords.y) : aTexCoords;
    gl_Position = projection * view * model * vec4(aPos, 1.0);
    if (flipY)
        gl_Position.y = -gl_Position.y;
}
