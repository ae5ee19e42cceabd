#version 330 core
// stereoshift-expect: deferred-unproject
// OpenGL 3.3 deferred point light: the view-space position is the interpolated frustum ray
// (z = -1) times the linear eye depth stored in the G-buffer's alpha; loose uniforms, Blinn-Phong,
// and the light's screen radius from projection[0][0].

uniform sampler2D gNormalDepth;   // rgb normal, a linear eye depth
uniform sampler2D gAlbedoSpec;
uniform mat4 projection;
uniform vec3 lightPosView;
uniform vec3 lightColor;
uniform float lightRadius;

in vec2 TexCoords;
in vec3 ViewRay;
out vec4 FragColor;

/* ---- stereoshift ---- */ vec3 stereoshift_view_ray_fragPos(vec3 stereoshift_p); /* ---- end stereoshift ---- */ void main()
{
    vec4 normalDepth = texture(gNormalDepth, TexCoords);
    vec3 fragPos = stereoshift_view_ray_fragPos(ViewRay * normalDepth.a);
    vec3 normal = normalize(normalDepth.rgb);
    vec4 albedoSpec = texture(gAlbedoSpec, TexCoords);

    vec3 lightDir = lightPosView - fragPos;
    float distance = length(lightDir);
    lightDir /= distance;
    vec3 viewDir = normalize(-fragPos);
    vec3 halfway = normalize(lightDir + viewDir);
    float diffuse = max(dot(normal, lightDir), 0.0);
    float specular = pow(max(dot(normal, halfway), 0.0), 32.0) * albedoSpec.a;
    float attenuation = clamp(1.0 - distance / lightRadius, 0.0, 1.0);
    // Fade the light's edge over a few pixels: its radius on screen at this depth.
    float screenRadius = lightRadius * projection[0][0] / max(-fragPos.z, 0.001);
    attenuation *= clamp(screenRadius, 0.0, 1.0);
    FragColor = vec4((albedoSpec.rgb * diffuse + specular) * lightColor * attenuation, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
vec3 stereoshift_view_ray_fragPos(vec3 stereoshift_p)
{
    if (eyeSign != 0.0)
        stereoshift_p.x = stereoshift_p.x - ((eyeSign * separation) * (abs(stereoshift_p.z) - convergence)) * (1.0 / projection[0][0]);
    return stereoshift_p;
}
// ---- end stereoshift ----
