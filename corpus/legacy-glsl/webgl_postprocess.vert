// stereoshift-expect: 2d
// WebGL1 full-screen quad for a post-processing pass: no #version, clip position with w = 1.
attribute vec2 aPosition;

varying vec2 vUv;

void main() {
    vUv = aPosition * 0.5 + 0.5;
    gl_Position = vec4(aPosition, 0.0, 1.0);
}
