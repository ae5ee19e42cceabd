// OpenGL 3.3 shadow mapping in the tutorial manner: the camera's MVP and the light's biased MVP
// are two loose uniforms. ShadowCoord is not a copy of the position: with equal data for both
// matrices it would look like one (a false "halo" report).
#version 330 core
layout(location = 0) in vec3 vertexPosition_modelspace;
layout(location = 1) in vec2 vertexUV;

out vec2 UV;
out vec4 ShadowCoord;

uniform mat4 MVP;
uniform mat4 DepthBiasMVP;

void main() {
    gl_Position = MVP * vec4(vertexPosition_modelspace, 1);
    ShadowCoord = DepthBiasMVP * vec4(vertexPosition_modelspace, 1);
    UV = vertexUV;
}
