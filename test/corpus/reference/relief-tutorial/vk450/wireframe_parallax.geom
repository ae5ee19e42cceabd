#version 450
layout(triangles) in;
layout(max_vertices = 3, triangle_strip) out;

invariant gl_Position;

layout(set = 0, binding = 1, std140) uniform Viewport
{
    vec2 size;
} viewport;

layout(set = 0, binding = 5, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) out vec2 outUV;
layout(location = 0) in vec2 inUV[3];
layout(location = 1) out vec3 outTangentViewPos;
layout(location = 1) in vec3 inTangentViewPos[3];
layout(location = 2) out vec3 outTangentFragPos;
layout(location = 2) in vec3 inTangentFragPos[3];
layout(location = 3) noperspective out vec3 outEdgeDistance;

void main()
{
    vec2 p[3];
    for (int i = 0; i < 3; i++)
    {
        p[i] = (viewport.size * gl_in[i].gl_Position.xy) / vec2(gl_in[i].gl_Position.w);
    }
    float area = abs(((p[1].x - p[0].x) * (p[2].y - p[0].y)) - ((p[2].x - p[0].x) * (p[1].y - p[0].y)));
    for (int i_1 = 0; i_1 < 3; i_1++)
    {
        vec3 edge = vec3(0.0);
        edge[i_1] = area / length(p[(i_1 + 2) % 3] - p[(i_1 + 1) % 3]);
        gl_Position = gl_in[i_1].gl_Position;
        outUV = inUV[i_1];
        outTangentViewPos = inTangentViewPos[i_1];
        outTangentFragPos = inTangentFragPos[i_1];
        outEdgeDistance = edge;
        if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
        {
            precise float _176 = gl_Position.w - stereo.convergence;
            precise float _177 = stereo.eyeSign * stereo.separation;
            precise float _178 = _177 * _176;
            precise float _179 = gl_Position.x + _178;
            gl_Position.x = _179;
        }
        EmitVertex();
    }
    EndPrimitive();
}

