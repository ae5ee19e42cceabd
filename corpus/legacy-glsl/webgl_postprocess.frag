// stereoshift-expect: fragment
// WebGL1 edge-detect pass: no #version, GL_OES_standard_derivatives for fwidth, default precision.
#extension GL_OES_standard_derivatives : enable
precision mediump float;

uniform sampler2D uScene;
uniform float uEdgeStrength;

varying vec2 vUv;

void main() {
    vec4 color = texture2D(uScene, vUv);
    float luma = dot(color.rgb, vec3(0.299, 0.587, 0.114));
    float edge = clamp(fwidth(luma) * uEdgeStrength, 0.0, 1.0);
    gl_FragColor = vec4(mix(color.rgb, vec3(0.0), edge), 1.0);
}
