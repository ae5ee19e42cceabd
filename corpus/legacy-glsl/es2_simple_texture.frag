#version 100
// stereoshift-expect: fragment
// GL ES 2.0 SDK style fragment shader: default precision, s_ sampler, texture2D into gl_FragColor.
precision mediump float;

varying vec2 v_texCoord;

uniform sampler2D s_texture;

void main()
{
    gl_FragColor = texture2D(s_texture, v_texCoord);
}
