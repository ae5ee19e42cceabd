#version 450
layout(points) in;
layout(max_vertices = 4, triangle_strip) out;

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform CameraUBO
{
    mat4 viewProj;
    vec4 cameraRight;
    vec4 cameraUp;
} camera;

layout(set = 0, binding = 2, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec2 outUV;
layout(location = 0) in vec4 inColor[1];
layout(location = 1) in float inSize[1];

void emitCorner(vec3 center, vec2 corner, float size, vec4 color)
{
    vec3 world = center + (((camera.cameraRight.xyz * corner.x) + (camera.cameraUp.xyz * corner.y)) * size);
    outColor = color;
    outUV = corner + vec2(0.5);
    vec4 _72 = vec4(world, 1.0);
    vec4 _73 = camera.viewProj * _72;
    gl_Position = _73;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _171 = gl_Position.w - stereo.convergence;
        precise float _172 = stereo.eyeSign * stereo.separation;
        precise float _173 = _172 * _171;
        precise float _174 = gl_Position.x + _173;
        gl_Position.x = _174;
    }
    EmitVertex();
}

void main()
{
    if (inColor[0].w <= 0.0)
    {
        return;
    }
    vec3 center = gl_in[0].gl_Position.xyz;
    vec3 param = center;
    vec2 param_1 = vec2(-0.5);
    float param_2 = inSize[0];
    vec4 param_3 = inColor[0];
    emitCorner(param, param_1, param_2, param_3);
    vec3 param_4 = center;
    vec2 param_5 = vec2(0.5, -0.5);
    float param_6 = inSize[0];
    vec4 param_7 = inColor[0];
    emitCorner(param_4, param_5, param_6, param_7);
    vec3 param_8 = center;
    vec2 param_9 = vec2(-0.5, 0.5);
    float param_10 = inSize[0];
    vec4 param_11 = inColor[0];
    emitCorner(param_8, param_9, param_10, param_11);
    vec3 param_12 = center;
    vec2 param_13 = vec2(0.5);
    float param_14 = inSize[0];
    vec4 param_15 = inColor[0];
    emitCorner(param_12, param_13, param_14, param_15);
    EndPrimitive();
}

