#version 100
// stereoshift-expect: fragment
// GL ES 2.0 SDK style G-buffer fragment shader: GL_EXT_draw_buffers, three gl_FragData targets.
#extension GL_EXT_draw_buffers : enable
precision mediump float;

varying vec3 v_normal;
varying vec3 v_worldPos;

uniform vec4 u_albedo;

void main()
{
    gl_FragData[0] = u_albedo;
    gl_FragData[1] = vec4(normalize(v_normal) * 0.5 + 0.5, 1.0);
    gl_FragData[2] = vec4(v_worldPos, 1.0);
}
