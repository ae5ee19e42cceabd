// stereoshift-expect: fragment
// WebGL1 lesson style textured fragment shader: no #version, default precision, texture2D into gl_FragColor.
precision mediump float;

varying vec2 vTextureCoord;

uniform sampler2D uSampler;

void main(void) {
    gl_FragColor = texture2D(uSampler, vec2(vTextureCoord.s, vTextureCoord.t));
}
