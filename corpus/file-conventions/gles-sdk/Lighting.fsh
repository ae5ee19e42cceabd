#version 300 es
// stereoshift-expect: fragment
// GL ES SDK-style textured fragment shader (`.fsh`), modulated by the per-vertex diffuse term.
precision mediump float;
uniform sampler2D s_texture;
in mediump vec2 v_texCoord;
in lowp float v_diffuse;
out vec4 o_color;

void main()
{
    o_color = texture(s_texture, v_texCoord) * (0.2 + v_diffuse);
}
