// OpenGL 3.3 point-sprite expansion in the tutorial manner: loose uniforms, view-space points in,
// a camera-facing quad out. Given alone: verify runs it behind a synthesized vertex stage.
#version 330 core
layout (points) in;
layout (triangle_strip, max_vertices = 4) out;

uniform mat4 projection;
uniform float particleSize;

in vec3 vColor[];
out vec3 fColor;
out vec2 fUV;

void main() {
    vec4 center = gl_in[0].gl_Position;
    for (int i = 0; i < 4; ++i) {
        vec2 corner = vec2(i % 2, i / 2) * 2.0 - 1.0;
        fColor = vColor[0];
        fUV = corner * 0.5 + 0.5;
        gl_Position = projection * (center + vec4(corner * particleSize, 0.0, 0.0));
        EmitVertex();
    }
    EndPrimitive();
}
