#version 460
#extension GL_EXT_ray_query : require
layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;
layout(set = 0, binding = 1) uniform Camera { mat4 viewProj; } cam;
layout(location = 0) in vec3 inPos;
layout(location = 0) out float lit;
void main() {
  rayQueryEXT q;
  rayQueryInitializeEXT(q, tlas, gl_RayFlagsTerminateOnFirstHitEXT, 0xFF, inPos, 0.01, vec3(0, 1, 0), 100.0);
  while (rayQueryProceedEXT(q)) {}
  lit = rayQueryGetIntersectionTypeEXT(q, true) == gl_RayQueryCommittedIntersectionNoneEXT ? 1.0 : 0.0;
  gl_Position = cam.viewProj * vec4(inPos, 1.0);
}
