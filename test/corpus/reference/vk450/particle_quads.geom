#version 450
// stereoshift-expect: shift
// Billboard geometry shader: expands each particle point into a camera-facing quad using camera right/up vectors.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 viewProj;
    vec4 cameraRight;
    vec4 cameraUp;
} camera;

layout(location = 0) in vec4 inColor[];
layout(location = 1) in float inSize[];

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec2 outUV;

/* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void emitCorner(vec3 center, vec2 corner, float size, vec4 color)
{
    vec3 world = center + (camera.cameraRight.xyz * corner.x + camera.cameraUp.xyz * corner.y) * size;
    outColor = color;
    outUV = corner + 0.5;
    gl_Position = camera.viewProj * vec4(world, 1.0);
    { stereoshift_shiftPosition(); EmitVertex(); }
}

void main()
{
    if (inColor[0].a <= 0.0)
        return;
    vec3 center = gl_in[0].gl_Position.xyz;
    emitCorner(center, vec2(-0.5, -0.5), inSize[0], inColor[0]);
    emitCorner(center, vec2( 0.5, -0.5), inSize[0], inColor[0]);
    emitCorner(center, vec2(-0.5,  0.5), inSize[0], inColor[0]);
    emitCorner(center, vec2( 0.5,  0.5), inSize[0], inColor[0]);
    EndPrimitive();
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 2, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
void stereoshift_shiftPosition()
{
    if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
        gl_Position.x = stereoshift_x;
    }
}
// ---- end stereoshift ----
