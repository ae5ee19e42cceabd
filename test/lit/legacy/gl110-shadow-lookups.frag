#version 120
// The 1xx shadow lookups in every form: with a LOD bias, on a rectangle texture
// (GL_ARB_texture_rectangle), on an array (GL_EXT_texture_array), with gradients
// (GL_ARB_shader_texture_lod). The analysis translation gives each a vec4 helper; the fragment stage
// needs nothing, so the output is the input byte for byte.
// RUN: %stereoshift %s -o %t.frag --report %t.json
// RUN: cmp %s %t.frag
// RUN: FileCheck %s --input-file %t.json
// CHECK: "output": "copied"
#extension GL_ARB_texture_rectangle : enable
#extension GL_EXT_texture_array : enable
#extension GL_ARB_shader_texture_lod : enable
uniform sampler2DShadow uShadow;
uniform sampler2DRectShadow uRectShadow;
uniform sampler2DArrayShadow uCascades;
varying vec4 vShadowCoord;
void main()
{
    float lit = shadow2DProj(uShadow, vShadowCoord, 1.0).r;
    lit *= shadow2D(uShadow, vShadowCoord.xyz, 0.5).r;
    lit *= shadow2DRect(uRectShadow, vShadowCoord.xyz * vec3(64.0, 64.0, 1.0)).r;
    lit *= shadow2DArray(uCascades, vec4(vShadowCoord.xy, 2.0, vShadowCoord.z)).r;
    lit *= shadow2DGradARB(uShadow, vShadowCoord.xyz, dFdx(vShadowCoord.xy), dFdy(vShadowCoord.xy)).r;
    gl_FragColor = vec4(vec3(lit), 1.0);
}
