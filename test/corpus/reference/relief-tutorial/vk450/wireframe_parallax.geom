#version 450
// stereoshift-expect: shift
// Parallax mapping with a wireframe overlay, geometry stage: adds each vertex's distance to the opposite edge and passes the tangent-space vectors on by location.
layout (triangles) in;
layout (triangle_strip, max_vertices = 3) out;

layout (binding = 1) uniform Viewport { vec2 size; } viewport;

layout (location = 0) in vec2 inUV[];
layout (location = 1) in vec3 inTangentViewPos[];
layout (location = 2) in vec3 inTangentFragPos[];

layout (location = 0) out vec2 outUV;
layout (location = 1) out vec3 outTangentViewPos;
layout (location = 2) out vec3 outTangentFragPos;
layout (location = 3) noperspective out vec3 outEdgeDistance;

/* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main()
{
	vec2 p[3];
	for (int i = 0; i < 3; i++)
		p[i] = viewport.size * gl_in[i].gl_Position.xy / gl_in[i].gl_Position.w;
	float area = abs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
	for (int i = 0; i < 3; i++) {
		vec3 edge = vec3(0.0);
		edge[i] = area / length(p[(i + 2) % 3] - p[(i + 1) % 3]);
		gl_Position = gl_in[i].gl_Position;
		outUV = inUV[i];
		outTangentViewPos = inTangentViewPos[i];
		outTangentFragPos = inTangentFragPos[i];
		outEdgeDistance = edge;
		{ stereoshift_shiftPosition(); EmitVertex(); }
	}
	EndPrimitive();
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 5, std140) uniform StereoParams
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
