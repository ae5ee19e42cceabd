#version 330

uniform sampler2D uGDepth;
uniform vec2 uViewportSize;
uniform mat4 uInvViewProj;
uniform sampler2D uGNormal;
uniform sampler2D uGAlbedo;
uniform vec3 uLightDir;
uniform vec3 uCameraPos;
uniform vec3 uLightColor;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

in vec2 vUV;
out vec4 fragColor;

void main()
{
    float depth = texture(uGDepth, vUV).x;
    if (depth >= 1.0)
    {
        discard;
    }
    vec2 ndc = ((gl_FragCoord.xy / uViewportSize) * 2.0) - vec2(1.0);
    vec4 _57 = uInvViewProj * vec4(ndc, (depth * 2.0) - 1.0, 1.0);
    vec4 _144 = _57 - (uInvViewProj[0] * ((eyeSign * separation) * (1.0 - (convergence * _57.w))));
    bvec4 _146 = bvec4(eyeSign != 0.0);
    vec4 q = vec4(_146.x ? _144.x : _57.x, _146.y ? _144.y : _57.y, _146.z ? _144.z : _57.z, _146.w ? _144.w : _57.w);
    vec3 worldPos = q.xyz / vec3(q.w);
    vec3 n = normalize((texture(uGNormal, vUV).xyz * 2.0) - vec3(1.0));
    vec3 albedo = texture(uGAlbedo, vUV).xyz;
    vec3 l = normalize(-uLightDir);
    vec3 h = normalize(l + normalize(uCameraPos - worldPos));
    float diffuse = max(dot(n, l), 0.0);
    float specular = pow(max(dot(n, h), 0.0), 32.0) * diffuse;
    fragColor = vec4(uLightColor * ((albedo * diffuse) + vec3(specular)), 1.0);
}

