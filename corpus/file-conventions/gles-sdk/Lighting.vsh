#version 300 es
// stereoshift-expect: shift
// GL ES SDK-style per-vertex lighting vertex shader (`.vsh`).
uniform highp mat4 u_mvpMatrix;
uniform highp mat3 u_normalMatrix;
uniform highp vec3 u_lightDirection;
in highp vec4 a_position;
in highp vec3 a_normal;
in mediump vec2 a_texCoord;
out mediump vec2 v_texCoord;
out lowp float v_diffuse;

void main()
{
    gl_Position = u_mvpMatrix * a_position;
    v_texCoord = a_texCoord;
    v_diffuse = max(dot(normalize(u_normalMatrix * a_normal), u_lightDirection), 0.0);
}
