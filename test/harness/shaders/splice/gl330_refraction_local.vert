#version 330 core
// Glass: the clip position kept in a local, given to gl_Position, and a refraction offset in
// screen space derived from it and the view-space normal.
uniform mat4 uProjection;
uniform mat4 uModelView;
uniform float uStrength;
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
out vec2 vScreenOffsetUV;
out vec3 vNormal;
void main()
{
    vec4 viewPos = uModelView * vec4(aPosition, 1.0);
    vNormal = mat3(uModelView) * aNormal;
    vec4 clip = uProjection * viewPos;
    gl_Position = clip;
    vScreenOffsetUV = (clip.xy / clip.w) * 0.5 + 0.5 + vNormal.xy * uStrength;
}
