#version 330

uniform sampler2D gNormalDepth;
uniform sampler2D gAlbedoSpec;
uniform vec3 lightPosView;
uniform float lightRadius;
uniform mat4 projection;
uniform vec3 lightColor;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

in vec2 TexCoords;
in vec3 ViewRay;
out vec4 FragColor;

void main()
{
    vec4 normalDepth = texture(gNormalDepth, TexCoords);
    vec3 _31 = ViewRay * normalDepth.w;
    float _139 = _31.z;
    vec3 _149 = _31;
    _149.x = _31.x - (((eyeSign * separation) * (((_139 < 0.0) ? (-_139) : _139) - convergence)) * (1.0 / projection[0].x));
    bvec3 _151 = bvec3(eyeSign != 0.0);
    vec3 fragPos = vec3(_151.x ? _149.x : _31.x, _151.y ? _149.y : _31.y, _151.z ? _149.z : _31.z);
    vec3 normal = normalize(normalDepth.xyz);
    vec4 albedoSpec = texture(gAlbedoSpec, TexCoords);
    vec3 lightDir = lightPosView - fragPos;
    float _distance = length(lightDir);
    lightDir /= vec3(_distance);
    vec3 viewDir = normalize(-fragPos);
    vec3 halfway = normalize(lightDir + viewDir);
    float diffuse = max(dot(normal, lightDir), 0.0);
    float specular = pow(max(dot(normal, halfway), 0.0), 32.0) * albedoSpec.w;
    float attenuation = clamp(1.0 - (_distance / lightRadius), 0.0, 1.0);
    float screenRadius = (lightRadius * projection[0].x) / max(-fragPos.z, 0.001000000047497451305389404296875);
    attenuation *= clamp(screenRadius, 0.0, 1.0);
    FragColor = vec4((((albedoSpec.xyz * diffuse) + vec3(specular)) * lightColor) * attenuation, 1.0);
}

