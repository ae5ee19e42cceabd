// Halo by value, the reverse, OpenGL 3.3 in the tutorial manner: a planar mirror / water surface
// writes the clip position to the varying its fragment shader looks the reflection up with
// (textureProj(reflection, ReflectionCoord)) and reads gl_Position back from that varying. The
// varying and gl_Position must both carry the shifted x, the same in each eye.
#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec2 aTexCoords;

out vec2 TexCoords;
out vec4 ReflectionCoord;

uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;

void main() {
    TexCoords = aTexCoords;
    ReflectionCoord = projection * view * model * vec4(aPos, 1.0);
    gl_Position = ReflectionCoord;
}
