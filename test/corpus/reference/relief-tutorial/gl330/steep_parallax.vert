#version 330 core
// stereoshift-expect: per-eye-view
// Steep-parallax floor tile, vertex stage: loose tangent-space varyings, tangent frame built from normal and tangent.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
layout (location = 3) in vec3 aTangent;

out vec2 TexCoords;
out vec3 TangentViewPos;
out vec3 TangentFragPos;

uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform vec3 viewPos;

/* ---- stereoshift ---- */ vec3 stereoshift_eye_viewPos(vec3 stereoshift_camera); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
{
    vec3 worldPos = vec3(model * vec4(aPos, 1.0));
    vec3 N = normalize(mat3(model) * aNormal);
    vec3 T = normalize(mat3(model) * aTangent);
    T = normalize(T - dot(T, N) * N);
    vec3 B = cross(N, T);
    mat3 TBN = transpose(mat3(T, B, N));

    TexCoords = aTexCoords;
    TangentViewPos = TBN * stereoshift_eye_viewPos(viewPos);
    TangentFragPos = TBN * worldPos;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
vec3 stereoshift_eye_viewPos(vec3 stereoshift_camera)
{
    return stereoshift_camera + (inverse(projection * view) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz;
}
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
