// WebGL 1 water surface: the clip position copied for a projective reflection lookup, and the
// screen UV of the refraction map computed from it (a derived halo output).
precision mediump float;
attribute vec3 aPosition;
attribute vec2 aUV;
uniform highp mat4 uModelViewProjection;
varying vec4 vReflectClip;
varying vec2 vRefractUV;
varying vec2 vUV;
void main()
{
    gl_Position = uModelViewProjection * vec4(aPosition, 1.0);
    vReflectClip = gl_Position;
    vRefractUV = gl_Position.xy / gl_Position.w * 0.5 + 0.5;
    vUV = aUV;
}
