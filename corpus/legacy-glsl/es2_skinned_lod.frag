#version 100
// stereoshift-expect: fragment
// GL ES 2.0 style detail-texture fragment shader: GL_EXT_shader_texture_lod for an explicit-LOD lookup.
#extension GL_EXT_shader_texture_lod : enable
precision mediump float;

uniform sampler2D u_detail;
uniform float u_detailLod;

varying vec2 v_uv;

void main()
{
    vec4 detail = texture2DLodEXT(u_detail, v_uv * 8.0, u_detailLod);
    gl_FragColor = vec4(detail.rgb, 1.0);
}
