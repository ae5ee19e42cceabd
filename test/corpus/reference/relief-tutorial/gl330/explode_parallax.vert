#version 330 core
// stereoshift-expect: per-eye-view
// Exploding parallax-mapped model, vertex stage: tangent-space camera and position handed to a geometry stage in an interface block.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
layout (location = 3) in vec3 aTangent;

out VS_OUT {
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} vs_out;

uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform vec3 viewPos;

/* ---- stereoshift ---- */ vec3 stereoshift_eye_viewPos(vec3 stereoshift_camera); /* ---- end stereoshift ---- */ void main()
{
    vec3 worldPos = vec3(model * vec4(aPos, 1.0));
    vec3 N = normalize(mat3(model) * aNormal);
    vec3 T = normalize(mat3(model) * aTangent);
    vec3 B = cross(N, T);
    mat3 TBN = transpose(mat3(T, B, N));
    vs_out.TexCoords = aTexCoords;
    vs_out.TangentViewPos = TBN * stereoshift_eye_viewPos(viewPos);
    vs_out.TangentFragPos = TBN * worldPos;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
vec3 stereoshift_eye_viewPos(vec3 stereoshift_camera)
{
    return stereoshift_camera + (inverse(projection * view) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz;
}
// ---- end stereoshift ----
