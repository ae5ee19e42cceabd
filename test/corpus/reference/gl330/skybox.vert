#version 330
// stereoshift-expect: shift
// Skybox vertex shader: rotation-only view matrix, depth forced to the far plane with pos.xyww.

layout(location = 0) in vec3 aPosition;

uniform mat4 uView;
uniform mat4 uProjection;

out vec3 vDirection;

void main_stereoshift_mono()
{
    // Drop the translation so the box stays centred on the camera.
    mat4 rotationOnly = mat4(mat3(uView));
    vec4 pos = uProjection * rotationOnly * vec4(aPosition, 1.0);
    vDirection = aPosition;
    gl_Position = pos.xyww;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
