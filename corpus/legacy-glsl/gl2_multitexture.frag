#version 120
// stereoshift-expect: fragment
// GL 2.1 tutorial multitexturing fragment shader: gl_Color and gl_TexCoord[] inputs, a sampler named `texture`.
uniform sampler2D texture;
uniform sampler2D lightmap;

void main()
{
    vec4 base = texture2D(texture, gl_TexCoord[0].st);
    vec4 light = texture2D(lightmap, gl_TexCoord[1].st);
    gl_FragColor = gl_Color * base * light;
}
