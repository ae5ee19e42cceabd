#version 330 core
// stereoshift-expect: per-eye-view
// Parallax demo with selectable modes, vertex stage: no camera uniform, the eye position is the translation of inverse(view).
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
layout (location = 3) in vec4 aTangent;

out vec2 vUV;
out vec3 vTangentEye;
out vec3 vTangentPos;

uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProjection;

/* ---- stereoshift ---- */ mat4 stereoshift_eye_inverse_uView(mat4 stereoshift_camera); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
{
    vec4 world = uModel * vec4(aPos, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    vec3 b = cross(n, t) * aTangent.w;
    mat3 toTangent = transpose(mat3(t, b, n));

    vec3 eye = stereoshift_eye_inverse_uView(inverse(uView))[3].xyz;
    vUV = aTexCoords;
    vTangentEye = toTangent * eye;
    vTangentPos = toTangent * world.xyz;
    gl_Position = uProjection * uView * world;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
mat4 stereoshift_eye_inverse_uView(mat4 stereoshift_camera)
{
    stereoshift_camera[3] = stereoshift_camera[3] + vec4((inverse(uProjection * uView) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
    return stereoshift_camera;
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
