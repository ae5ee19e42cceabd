#version 330
// stereoshift-expect: fragment
// Skybox fragment shader: cube map lookup with exposure and a horizon tint.

in vec3 vDirection;

uniform samplerCube uSkyCube;
uniform float uExposure;
uniform vec3 uHorizonTint;

out vec4 fragColor;

void main()
{
    vec3 dir = normalize(vDirection);
    vec3 sky = texture(uSkyCube, dir).rgb;
    float horizon = 1.0 - clamp(abs(dir.y) * 4.0, 0.0, 1.0);
    sky = mix(sky, sky * uHorizonTint, horizon * 0.5);
    fragColor = vec4(sky * uExposure, 1.0);
}
