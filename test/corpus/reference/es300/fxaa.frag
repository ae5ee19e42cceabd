#version 300 es
// stereoshift-expect: fragment
// Anti-aliasing post-process fragment shader: simplified FXAA edge blend on luma.

precision mediump float;

in highp vec2 vUV;
in highp vec4 vNeighbourUV;

uniform sampler2D uColor;
uniform highp vec2 uInvResolution;

out vec4 fragColor;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main()
{
    vec3 rgbM = texture(uColor, vUV).rgb;
    float lNW = luma(texture(uColor, vNeighbourUV.xy).rgb);
    float lNE = luma(texture(uColor, vNeighbourUV.zy).rgb);
    float lSW = luma(texture(uColor, vNeighbourUV.xw).rgb);
    float lSE = luma(texture(uColor, vNeighbourUV.zw).rgb);
    float lM = luma(rgbM);

    float lMin = min(lM, min(min(lNW, lNE), min(lSW, lSE)));
    float lMax = max(lM, max(max(lNW, lNE), max(lSW, lSE)));
    if (lMax - lMin < max(0.0312, lMax * 0.125)) {
        fragColor = vec4(rgbM, 1.0);
        return;
    }

    vec2 dir = vec2(-((lNW + lNE) - (lSW + lSE)), (lNW + lSW) - (lNE + lSE));
    float reduce = max((lNW + lNE + lSW + lSE) * 0.03125, 1.0 / 128.0);
    float scale = 1.0 / (min(abs(dir.x), abs(dir.y)) + reduce);
    dir = clamp(dir * scale, vec2(-8.0), vec2(8.0)) * uInvResolution;

    vec3 a = 0.5 * (texture(uColor, vUV - dir * (1.0 / 6.0)).rgb + texture(uColor, vUV + dir * (1.0 / 6.0)).rgb);
    fragColor = vec4(a, 1.0);
}
