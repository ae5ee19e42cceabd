#version 120
// stereoshift-expect: fragment
// GL 2.1 tutorial shadow-mapping fragment shader: shadow2DProj on a sampler2DShadow, gl_Color input.
uniform sampler2DShadow shadowMap;

varying vec4 shadowCoord;
varying vec3 normal;

void main()
{
    float lit = shadow2DProj(shadowMap, shadowCoord).r;
    float ambient = 0.3;
    gl_FragColor = vec4(gl_Color.rgb * (ambient + (1.0 - ambient) * lit), gl_Color.a);
}
