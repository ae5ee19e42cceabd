// Deferred lighting per eye against ground truth (deferred-unprojection pass, docs/stereo-math.md section 4).
//
// Per eye, on lavapipe: a G-buffer (albedo, normal, depth) of a small scene rendered with that eye's
// stereo projection (mono P with row 0 = [p00, 0, p02 - e S, -e S C]), then a full-screen lighting
// pass (a close copy of corpus/vk450/deferred_light.frag: NDC from gl_FragCoord, Vulkan [0,1] depth,
// world position through the inverse view-projection; textures instead of subpass inputs, a point
// light with attenuation and a smooth world-space pattern instead of the shadow map) three ways:
//   truth:    the original lighting shader with the true per-eye inverse (P_stereo V)^-1;
//   fix:      stereoshift's lighting shader with the mono inverse (P V)^-1 and the eye parameters;
//   baseline: the original lighting shader with the mono inverse (what a mono engine does).
// Two checks:
//   1. the rebuilt world position itself, read back bit-exactly (the shader writes the float's bits
//      as RGBA8), against the exact position computed in double: truth and fix must both be within
//      a first-order rounding bound computed per pixel (see positionBound());
//   2. the lit image: PSNR and max channel difference of fix and baseline against truth. The fix
//      must match to the 8-bit rounding of the output (at most 1 level), the baseline must not.
// PNGs of each eye (truth, fix, baseline) and a red/cyan anaglyph of the fix are written for a person.
// Both checks run for the GLSL lighting shader and for its HLSL relative (kLightingHlsl, through
// glslang's HLSL front end), with the same scene, matrices and bounds.
// A third check covers the view-ray form (docs/stereo-math.md section 4, view rays): the lighting
// shader kViewRayFrag rebuilds the view-space point as ray * (linearDepth / -ray.z) with the ray
// from gl_FragCoord through the inverse projection; the G-buffer's depth of each eye, linearised,
// is read back, and the rebuilt point of fix and mono baseline is compared with the exact one.
#include "test/harness/position_rebuild_math.h"
#include "transpiler/verify/stereo_verify.h"
#include "transpiler/frontend/front_end.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

const char* kGBufferVert = R"(#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 proj; mat4 view; } cam;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inAlbedo;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vAlbedo;
void main() {
  vNormal = inNormal;
  vAlbedo = inAlbedo;
  gl_Position = cam.proj * cam.view * vec4(inPosition, 1.0);
}
)";

// One G-buffer target at a time (the harness renders into a single RGBA8 target).
const char* kGBufferAlbedoFrag = R"(#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vAlbedo;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(vAlbedo, 1.0); }
)";

const char* kGBufferNormalFrag = R"(#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vAlbedo;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(normalize(vNormal) * 0.5 + 0.5, 1.0); }
)";

// corpus/vk450/deferred_light.vert
const char* kFullScreenVert = R"(#version 450
layout(location = 0) out vec2 outUV;
out gl_PerVertex { vec4 gl_Position; };
void main() {
  const vec2 positions[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
  vec2 p = positions[gl_VertexIndex];
  outUV = p * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// The full-screen triangle handing on a copy of its clip position's x and y times a w (location 0)
// and that w alone (location 1), as an engine's light pass hands the screen position to a pixel
// shader that divides one by the other (`v1.xy / v2.x`).
const char* kClipCopyVert = R"(#version 450
layout(location = 0) out vec4 outClipCopy;
layout(location = 1) out float outW;
out gl_PerVertex { vec4 gl_Position; };
void main() {
  const vec2 positions[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
  vec2 p = positions[gl_VertexIndex];
  outClipCopy = vec4(p * 1.75, 0.0, 0.0);
  outW = 1.75;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

const char* kLightingFrag = R"(#version 450
layout(set = 0, binding = 0) uniform FrameUBO {
    mat4 invViewProj;
    vec4 viewportSize;   // xy = pixels, zw = 1 / pixels
    vec4 lightPosition;  // xyz = world position, w = radius
    vec4 lightColor;
} frame;

layout(set = 1, binding = 0) uniform sampler2D gAlbedo;
layout(set = 1, binding = 1) uniform sampler2D gNormal;
layout(set = 1, binding = 2) uniform sampler2D gDepth;

layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;

void main()
{
    float depth = texture(gDepth, inUV).r;
    vec2 ndc = gl_FragCoord.xy * frame.viewportSize.zw * 2.0 - 1.0;
    vec4 q = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec3 p = q.xyz / q.w;
#ifdef POSITION_COMPONENT
    outColor = unpackUnorm4x8(floatBitsToUint(p[POSITION_COMPONENT]));
#else
    if (depth >= 1.0) {
        outColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 albedo = texture(gAlbedo, inUV).rgb;
    vec3 n = normalize(texture(gNormal, inUV).xyz * 2.0 - 1.0);
    vec3 toLight = frame.lightPosition.xyz - p;
    float dist = length(toLight);
    float atten = clamp(1.0 - dist / frame.lightPosition.w, 0.0, 1.0);
    float ndl = max(dot(n, toLight / dist), 0.0);
    // A smooth world-space pattern: a misplaced position shows on every surface, lit or not, and
    // rounding-level position errors stay far below one 8-bit level.
    float pattern = 0.7 + 0.3 * sin(4.0 * p.x) * sin(4.0 * p.y + 3.0 * p.z);
    outColor = vec4(albedo * pattern * (0.3 + frame.lightColor.rgb * ndl * atten * atten), 1.0);
#endif
}
)";

// The HLSL relative of kLightingFrag, a close copy of corpus/hlsl/point_light.frag.hlsl made to fit
// the scene: the same cbuffer contents and bindings (explicit [[vk::binding(N, S)]]: set 0 binding 0
// the frame constants, set 1 bindings 0-2 the G-buffer), NDC from SV_Position (Vulkan convention,
// no y flip, as the scene's projection is Vulkan's), the depth by Texture2D::Load at the pixel,
// world position through mul(InvViewProj, float4(ndc, depth, 1)). HLSL `column_major` (the default)
// float4x4 has the same memory layout as GLSL's mat4, so both shaders get the same bytes.
// POSITION_COMPONENT writes the float's bits as RGBA8 (k / 255 converts back to exactly k).
const char* kLightingHlsl = R"(
[[vk::binding(0, 0)]] cbuffer FrameUBO
{
    float4x4 InvViewProj;
    float4   ViewportSize;   // xy = pixels, zw = 1 / pixels
    float4   LightPosition;  // xyz = world position, w = radius
    float4   LightColor;
};

[[vk::binding(0, 1)]] Texture2D<float4> GAlbedo;
[[vk::binding(1, 1)]] Texture2D<float4> GNormal;
[[vk::binding(2, 1)]] Texture2D<float>  GDepth;

struct PSInput
{
    float4 Position : SV_Position;
};

float4 main(PSInput input) : SV_Target
{
    int3 pixel = int3(input.Position.xy, 0);
    float depth = GDepth.Load(pixel);
    float2 ndc = input.Position.xy * ViewportSize.zw * 2.0 - 1.0;
    float4 q = mul(InvViewProj, float4(ndc, depth, 1.0));
    float3 p = q.xyz / q.w;
#ifdef POSITION_COMPONENT
    uint bits = asuint(p[POSITION_COMPONENT]);
    return float4(bits & 0xffu, (bits >> 8) & 0xffu, (bits >> 16) & 0xffu, bits >> 24) / 255.0;
#else
    if (depth >= 1.0)
        return float4(0.0, 0.0, 0.0, 1.0);
    float3 albedo = GAlbedo.Load(pixel).rgb;
    float3 n = normalize(GNormal.Load(pixel).xyz * 2.0 - 1.0);
    float3 toLight = LightPosition.xyz - p;
    float dist = length(toLight);
    float atten = saturate(1.0 - dist / LightPosition.w);
    float ndl = max(dot(n, toLight / dist), 0.0);
    float pattern = 0.7 + 0.3 * sin(4.0 * p.x) * sin(4.0 * p.y + 3.0 * p.z);
    return float4(albedo * pattern * (0.3 + LightColor.rgb * ndl * atten * atten), 1.0);
#endif
}
)";

// The same lighting pass as a 3Dmigoto dump of a decompiled pixel shader (`<hash>-ps_replace.txt`),
// written here in the decompiler's conventions: one cbuffer array `cb0[7]` (cb0[0..3] the inverse
// view-projection, cb0[4] the viewport, cb0[5..6] the light), registers r0..r3 reused, the world
// position rebuilt by a `mad` chain over the matrix's columns, the depth by Load at SV_POSITION0,
// 3Dmigoto's declarations block. The G-buffer sits in space1 (set 1, as the scene feeds it);
// StereoParams at t125 is set 0 binding 125. POSITION_COMPONENT writes the float's bits as RGBA8.
const std::string kDumpPrologue = R"(// ---- Created with 3Dmigoto v1.3.16 (a test dump written for stereoshift)
cbuffer cb0 : register(b0)
{
  float4 cb0[7];
}

Texture2D<float4> t0 : register(t0, space1);
Texture2D<float4> t1 : register(t1, space1);
Texture2D<float4> t2 : register(t2, space1);


// 3Dmigoto declarations
#define cmp -
Texture2D<float4> StereoParams : register(t125);


void main(
  float4 v0 : SV_POSITION0,
  out float4 o0 : SV_Target0)
{
  float4 r0,r1,r2,r3;
  uint4 bitmask, uiDest;
  float4 fDest;

  r0.xy = (int2)v0.xy;
  r0.zw = float2(0,0);
  r1.x = t2.Load(r0.xyz).x;
  r2.xy = v0.xy * cb0[4].zw;
  r2.xy = r2.xy * float2(2,2) + float2(-1,-1);
)";
const std::string kDumpEpilogue = R"(#ifdef POSITION_COMPONENT
  uiDest.x = asuint(r2[POSITION_COMPONENT]);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
#else
  r0.w = cmp(r1.x >= 1.000000);
  if (r0.w != 0) {
    o0.xyzw = float4(0,0,0,1);
    return;
  }
  r3.xyz = cb0[5].xyz + -r2.xyz;
  r0.w = dot(r3.xyz, r3.xyz);
  r0.w = sqrt(r0.w);
  r3.xyz = r3.xyz / r0.www;
  r1.yzw = t1.Load(r0.xyz).xyz;
  r1.yzw = r1.yzw * float3(2,2,2) + float3(-1,-1,-1);
  r3.w = dot(r1.yzw, r1.yzw);
  r3.w = rsqrt(r3.w);
  r1.yzw = r1.yzw * r3.www;
  r3.w = saturate(dot(r1.yzw, r3.xyz));
  o0.xyz = t0.Load(r0.xyz).xyz * r3.www;
  o0.w = 1;
  return;
#endif
}
)";

// Column storage, as the decompiler writes `mul(InvViewProj, float4(ndc, depth, 1))` with a
// column_major matrix: `mad` over cb0[0..3], the matrix uploaded as it is (column-major).
const std::string kDumpMadLighting = kDumpPrologue + R"(  r3.xyzw = cb0[1].xyzw * r2.yyyy;
  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;
  r3.xyzw = r1.xxxx * cb0[2].xyzw + r3.xyzw;
  r3.xyzw = cb0[3].xyzw + r3.xyzw;
  r2.xyz = r3.xyz / r3.www;
)" + kDumpEpilogue;

// The same rebuild in a dump that kept the game's reflection data: the cbuffer's members by name
// (a float4x4 and two float4s over the same registers as cb0[7]), the decompiler reading one column
// of the matrix per `mad` as a swizzle of four of its elements. Column-major, uploaded as kDumpMad's.
std::string namedMatrixDump() {
  std::string text = kDumpMadLighting;
  auto replace = [&](const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  };
  replace("  float4 cb0[7];\n", "  float4x4 InvViewProj : packoffset(c0);\n  float4 Viewport : packoffset(c4);\n"
                                 "  float4 LightPos : packoffset(c5);\n  float4 LightColour : packoffset(c6);\n");
  replace("cbuffer cb0 : register(b0)", "cbuffer PerFrame : register(b0)");
  for (int column = 0; column < 4; ++column)
    replace("cb0[" + std::to_string(column) + "].xyzw", "InvViewProj._m0" + std::to_string(column) + "_m1" +
                                                         std::to_string(column) + "_m2" + std::to_string(column) + "_m3" +
                                                         std::to_string(column));
  replace("cb0[4]", "Viewport");
  replace("cb0[5]", "LightPos");
  return text;
}

// Row storage (a row_major matrix): one dp4 per component over cb0[0..3], q.w in another register
// than q.xyz; the matrix uploaded transposed.
const std::string kDumpDp4Lighting = kDumpPrologue + R"(  r2.z = r1.x;
  r2.w = 1;
  r3.x = dot(r2.xyzw, cb0[0].xyzw);
  r3.y = dot(r2.xyzw, cb0[1].xyzw);
  r3.z = dot(r2.xyzw, cb0[2].xyzw);
  r0.w = dot(r2.xyzw, cb0[3].xyzw);
  r2.xyz = r3.xyz / r0.www;
)" + kDumpEpilogue;

// The screen-to-world form (Unreal's `mul(float4(ScreenPosition * SceneDepth, SceneDepth, 1),
// ScreenToWorld)`) as a decompiled dump: the NDC scaled by the linear view depth (the G-buffer's
// positive view depth, set 1 binding 2), then a `mad` chain over the matrix's columns cb0[0..3]
// mapping (ndc * depth, depth, 1) to the world.
const std::string kDumpScreenToWorld = kDumpPrologue + R"(  r2.xy = r2.xy * r1.xx;
  r2.z = r1.x;
  r3.xyzw = cb0[1].xyzw * r2.yyyy;
  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;
  r3.xyzw = r2.zzzz * cb0[2].xyzw + r3.xyzw;
  r3.xyzw = cb0[3].xyzw + r3.xyzw;
  r2.xyz = r3.xyz / r3.www;
)" + kDumpEpilogue;

// The same map where the shader never reads the point's w (Unreal's `mul(float4(ScreenPosition *
// SceneDepth, SceneDepth, 1), ScreenToWorld).xyz`): the compiler keeps lanes x, y and z of the
// columns, no w and no divide (the map is affine).
const std::string kScreenToWorldPointChain = R"(  r2.xy = r2.xy * r1.xx;
  r3.xyz = cb0[1].xyz * r2.yyy;
  r3.xyz = r2.xxx * cb0[0].xyz + r3.xyz;
  r3.xyz = r1.xxx * cb0[2].xyz + r3.xyz;
  r2.xyz = cb0[3].xyz + r3.xyz;
)";
const std::string kDumpScreenToWorldPoint = kDumpPrologue + kScreenToWorldPointChain + kDumpEpilogue;

// A view vector from the camera (cb0[5]) to the rebuilt position, normalized (specular, Fresnel and
// reflections start from it), its component VIEW_COMPONENT written as the float's bits.
const std::string kDumpViewVector = kDumpPrologue + R"(  r3.xyzw = cb0[1].xyzw * r2.yyyy;
  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;
  r3.xyzw = r1.xxxx * cb0[2].xyzw + r3.xyzw;
  r3.xyzw = cb0[3].xyzw + r3.xyzw;
  r2.xyz = r3.xyz / r3.www;
  r3.xyz = cb0[5].xyz + -r2.xyz;
  r0.w = dot(r3.xyz, r3.xyz);
  r0.w = rsqrt(r0.w);
  r3.xyz = r3.xyz * r0.www;
  uiDest.x = asuint(r3[VIEW_COMPONENT]);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
}
)";

// A forward pass's dump (Unreal's materials: `mul(float4(SvPosition.xyz, 1),
// View.SVPositionToTranslatedWorld)`): the point it shades rebuilt from its own pixel position and
// depth, SV_Position read as it is, through a matrix from pixels held in cb0[0..3] as columns (a
// `mad` chain). Drawn over the scene's geometry with the eye's projection; its cbuffer at b1 (set 0,
// binding 1: the geometry's vertex stage has its camera at binding 0). POSITION_COMPONENT writes the
// float's bits as RGBA8.
const std::string kDumpForwardFromThePixel = R"(// ---- Created with 3Dmigoto v1.3.16 (a test dump written for stereoshift)
cbuffer cb0 : register(b1)
{
  float4 cb0[7];
}


// 3Dmigoto declarations
#define cmp -
Texture2D<float4> StereoParams : register(t125);


void main(
  float4 v0 : SV_POSITION0,
  out float4 o0 : SV_Target0)
{
  float4 r0,r1,r2,r3;
  uint4 bitmask, uiDest;
  float4 fDest;

  r3.xyzw = cb0[1].xyzw * v0.yyyy;
  r3.xyzw = v0.xxxx * cb0[0].xyzw + r3.xyzw;
  r3.xyzw = v0.zzzz * cb0[2].xyzw + r3.xyzw;
  r3.xyzw = cb0[3].xyzw + r3.xyzw;
  r2.xyz = r3.xyz / r3.www;
  uiDest.x = asuint(r2[POSITION_COMPONENT]);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
}
)";

// The view-ray form as a decompiled dump: the linear depth (the G-buffer's positive view depth, set 1
// binding 2) times the NDC, times the inverse projection's scales read from the camera rows
// (cb0[0].x = 1/P00, cb0[1].y = 1/P11), one component per statement; z = -depth.
const std::string kDumpViewRay = kDumpPrologue + R"(  r2.xy = r2.xy * r1.xx;
  r3.x = r2.x * cb0[0].x;
  r3.y = r2.y * cb0[1].y;
  r3.z = -r1.x;
  uiDest.x = asuint(r3[POSITION_COMPONENT]);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
}
)";

// The view-ray form: the pixel's far-plane point through the inverse projection is the ray, scaled
// so that its z is the linear view depth the G-buffer stores (a positive depth; view space -z).
// The uniform block shares FrameUBO's first two members, so renderLighting() feeds it.
// With REPROJECT defined the position is re-projected with the projection (after the lighting data
// renderLighting() writes to the frame block) and the output is the NDC x it lands at minus the
// pixel's own.
const char* kViewRayFrag = R"(#version 450
layout(set = 0, binding = 0) uniform FrameUBO {
    mat4 invProjection;
    vec4 viewportSize;   // xy = pixels, zw = 1 / pixels
#ifdef REPROJECT
    vec4 light[2];
    mat4 projection;
#endif
} frame;
layout(set = 1, binding = 2) uniform sampler2D gLinearDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main()
{
    vec2 ndc = gl_FragCoord.xy * frame.viewportSize.zw * 2.0 - 1.0;
    vec4 farPoint = frame.invProjection * vec4(ndc, 1.0, 1.0);
    vec3 ray = farPoint.xyz / farPoint.w;
    float linearDepth = texelFetch(gLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    vec3 viewPos = ray * (linearDepth / -ray.z);
#ifdef REPROJECT
    vec4 back = frame.projection * vec4(viewPos, 1.0);
    outColor = unpackUnorm4x8(floatBitsToUint(back.x / back.w - ndc.x));
#else
    outColor = unpackUnorm4x8(floatBitsToUint(viewPos[POSITION_COMPONENT]));
#endif
}
)";

constexpr uint32_t kSize = 256;
constexpr float kSeparation = 0.06f, kConvergence = 4.0f;
// Vulkan clip space (y down, depth 0..1), w = -z_eye; eye != 0 gives the stereo projection.
Mat4 projection(double eye) {
  const double f = 1.0 / std::tan(0.5), n = 0.1, far = 1000.0;
  Mat4 p{};
  p[0] = f;
  p[5] = -f;
  p[10] = far / (n - far);
  p[11] = -1.0;
  p[14] = n * far / (n - far);
  p[8] = -eye * kSeparation;                 // p02 - e S
  p[12] = -eye * kSeparation * kConvergence;  // -e S C
  return p;
}

// A camera a little off the origin, turned 8 degrees about y and 5 about x, so the inverse
// view-projection has no zero pattern the fix could depend on.
Mat4 view() {
  const double yaw = 8.0 * std::numbers::pi / 180.0, pitch = -5.0 * std::numbers::pi / 180.0;
  Mat4 rotateY{std::cos(yaw), 0, -std::sin(yaw), 0, 0, 1, 0, 0, std::sin(yaw), 0, std::cos(yaw), 0, 0, 0, 0, 1};
  Mat4 rotateX{1, 0, 0, 0, 0, std::cos(pitch), std::sin(pitch), 0, 0, -std::sin(pitch), std::cos(pitch), 0, 0, 0, 0, 1};
  Mat4 translate{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -0.4, -0.6, -0.2, 1};
  return multiply(rotateX, multiply(rotateY, translate));
}

template <class T>
void append(std::vector<uint8_t>& bytes, const T* data, size_t count) {
  size_t at = bytes.size();
  bytes.resize(at + sizeof(T) * count);
  std::memcpy(bytes.data() + at, data, sizeof(T) * count);
}

// Quads: four corners (counter-clockwise seen from the normal side), a normal and an albedo.
struct Quad {
  std::array<std::array<float, 3>, 4> corners;
  std::array<float, 3> normal, albedo;
};

VertexBuffer sceneVertices(const std::vector<Quad>& quads) {
  VertexBuffer vb;
  vb.stride = 36;
  vb.attributes = {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, VK_FORMAT_R32G32B32_SFLOAT, 12},
                   {2, VK_FORMAT_R32G32B32_SFLOAT, 24}};
  for (const auto& q : quads)
    for (int corner : {0, 1, 2, 0, 2, 3}) {
      append(vb.bytes, q.corners[corner].data(), 3);
      append(vb.bytes, q.normal.data(), 3);
      append(vb.bytes, q.albedo.data(), 3);
    }
  return vb;
}

// Surfaces from 1.5 to 24 eye units, in front of, at and behind the convergence distance (4).
std::vector<Quad> scene() {
  return {
      {{{{-12, -1.5f, -1}, {12, -1.5f, -1}, {12, -1.5f, -24}, {-12, -1.5f, -24}}}, {0, 1, 0}, {0.8f, 0.8f, 0.75f}},  // floor
      {{{{-20, -1.5f, -24}, {20, -1.5f, -24}, {20, 16, -24}, {-20, 16, -24}}}, {0, 0, 1}, {0.6f, 0.7f, 0.9f}},        // back wall
      {{{{-4, -1.5f, -6}, {-4, -1.5f, -16}, {-4, 3, -16}, {-4, 3, -6}}}, {1, 0, 0}, {0.9f, 0.5f, 0.4f}},       // left wall
      {{{{0.2f, -0.8f, -4}, {1.4f, -0.8f, -4}, {1.4f, 0.6f, -4}, {0.2f, 0.6f, -4}}}, {0, 0, 1}, {0.4f, 0.9f, 0.4f}},  // at C
      {{{{-0.5f, 0.1f, -1.6f}, {0.1f, 0.1f, -1.9f}, {0.1f, 0.7f, -1.9f}, {-0.5f, 0.7f, -1.6f}}},
       {0.447f, 0, 0.894f}, {0.95f, 0.85f, 0.3f}},  // near, tilted
      {{{{1.5f, -1.5f, -9}, {3.5f, -1.5f, -11}, {3.5f, 1.5f, -11}, {1.5f, 1.5f, -9}}}, {0.707f, 0, 0.707f}, {0.8f, 0.4f, 0.9f}},
  };
}

std::vector<uint32_t> compileOriginal(const char* name, const char* text, const TranspileOptions& options) {
  Diagnostics diags;
  FrontEndResult front = compileToSpirv(SourceFile{name, text}, options, diags);
  EXPECT_TRUE(front.ok) << diags.format();
  return front.spirv;
}

struct Transpiled {
  std::vector<uint32_t> spirv;
  uint32_t eyeSet = 0, eyeBinding = 0;
  nlohmann::json report;
};

// `splicedText`: converted to its own language (the GLSL splice wraps the product in its helper),
// and that text compiled here as a driver would; else converted to SPIR-V.
Transpiled compileTranspiled(const char* name, const char* text, TranspileOptions options, bool splicedText = false) {
  options.target = splicedText ? TargetLanguage::Auto : TargetLanguage::Spirv;
  TranspileResult r = transpile(SourceFile{name, text}, options);
  EXPECT_TRUE(r.ok) << r.diagnostics.format();
  EXPECT_TRUE(r.changed) << "the lighting shader was not fixed";
  Transpiled t;
  if (splicedText) {
    std::string route = r.report.value("route", std::string());
    EXPECT_TRUE(route == "glsl-source-splice" || route == "hlsl-pixel-source-splice") << r.report.dump(2);
    EXPECT_TRUE(r.output.find("stereoshift_unproject_") != std::string::npos ||
                r.output.find("stereoshift_view_ray_") != std::string::npos)
        << r.output;
    t.spirv = compileOriginal(name, r.output.c_str(), options);
  } else {
    t.spirv.resize(r.output.size() / 4);
    std::memcpy(t.spirv.data(), r.output.data(), t.spirv.size() * 4);
  }
  const auto& eye = r.report["passes"]["eye-params"];
  t.eyeSet = eye.value("set", 0u);
  t.eyeBinding = eye.value("binding", 0u);
  t.report = r.report;
  return t;
}

// The options a 3Dmigoto dump is converted with, as `stereoshift <hash>-ps_replace.txt --eye-source
// 3dmigoto` does it (StereoParams fed here as a uniform block for lavapipe).
TranspileOptions dumpConversion(TranspileOptions options) {
  options.target = TargetLanguage::Hlsl;
  options.eyeFrom3DMigoto = true;
  options.sourceTextFixes = true;
  options.eye.source = EyeSource::UniformBlock;
  options.eye.blockName = "stereoshift_StereoParams";
  return options;
}

// The dump converted: its text with the correction spliced in (route hlsl-pixel-splice), compiled here
// like the original.
std::vector<uint32_t> compileDumpFixed(const char* name, const char* text, TranspileOptions options,
                                       nlohmann::json* pass = nullptr) {
  TranspileResult r = transpile(SourceFile{name, text}, dumpConversion(options));
  EXPECT_TRUE(r.ok) << r.diagnostics.format();
  EXPECT_EQ(r.report.value("route", std::string()), "hlsl-pixel-splice") << r.report.dump(2);
  EXPECT_NE(r.output.find("StereoParams.Load"), std::string::npos) << r.output;
  EXPECT_EQ(r.report["passes"]["deferred-unprojection"]["fixed"].size(), 1u) << r.report.dump(2);
  if (pass) *pass = r.report["passes"]["deferred-unprojection"];
  return compileOriginal(name, r.output.c_str(), options);
}

struct GBuffer {
  SampledTexture albedo, normal, depth;
  std::vector<float> depthValues;
};

double psnr(double mse) { return mse == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse); }

struct ImageError {
  double mse = 0;
  int maxDifference = 0;
  size_t differing = 0;
};

ImageError compare(const RenderResult& truth, const RenderResult& other) {
  ImageError e;
  for (size_t i = 0; i < size_t(kSize) * kSize; ++i)
    for (int c = 0; c < 3; ++c) {
      int d = int(truth.pixels[4 * i + c]) - int(other.pixels[4 * i + c]);
      e.mse += double(d) * d;
      e.maxDifference = std::max(e.maxDifference, std::abs(d));
      if (d) ++e.differing;
    }
  e.mse /= 3.0 * kSize * kSize;
  return e;
}

// The float a shader wrote as its bits in the RGBA8 pixel `pixel` (the position checks read back
// exact values this way).
double bitsAt(const RenderResult& r, size_t pixel) {
  uint32_t bits = 0;
  for (int b = 0; b < 4; ++b) bits |= uint32_t(r.pixels[4 * pixel + b]) << (8 * b);
  float f;
  std::memcpy(&f, &bits, 4);
  return double(f);
}

// m * v in double.
std::array<double, 4> times(const Mat4& m, const std::array<double, 4>& v) {
  std::array<double, 4> r{};
  for (int row = 0; row < 4; ++row)
    for (int c = 0; c < 4; ++c) r[row] += m[c * 4 + row] * v[c];
  return r;
}

// How renderLighting() feeds a 3Dmigoto dump: the matrix uploaded as rows when `rows`, and with
// `stereoParams` the eye parameters as 3Dmigoto gives them (texel 0 of StereoParams at t125:
// eyeSign * separation, convergence, eyeSign).
struct DumpFeed {
  bool rows = false, stereoParams = false;
  std::optional<std::array<float, 4>> row5;  // cb0[5] instead of the light's position (a camera)
  // The matrix maps UV space: the inverse view-projection times uvToNdc() is uploaded (and the
  // sampler bound).
  bool uvSpace = false;
  // The matrix maps pixel positions (SV_Position's x and y as they are): the inverse view-projection
  // times pixelToNdc() is uploaded.
  bool pixelSpace = false;
  // A forward pass: the shader is drawn over the scene's geometry with the eye's projection (depth
  // tested), its cbuffer at set 0, binding 1, instead of over a full-screen triangle.
  bool forward = false;
  // A sampler at set 1, binding 3 (the dump's `SamplerState s3_s : register(s3, space1)`).
  bool sampler = false;
};

// NDC from the depth buffer's UV: ndc = 2 uv - 1 in x and y (Vulkan's y runs down, as the UV does).
Mat4 uvToNdc() { return {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, -1, -1, 0, 1}; }
// NDC from the pixel position: ndc = 2 p / size - 1 in x and y (exact in fp32: the size is a power of 2).
Mat4 pixelToNdc() { return {2.0 / kSize, 0, 0, 0, 0, 2.0 / kSize, 0, 0, 0, 0, 1, 0, -1, -1, 0, 1}; }

// A dump (kDumpPrologue's) that hands the pixel position to its rebuild as the rasterizer gives it
// (`r2.xy = v0.xy;`) instead of making NDC of it; "" if the prologue is not there.
std::string withThePixelReadAsItIs(std::string text) {
  const std::string ndc = "  r2.xy = v0.xy * cb0[4].zw;\n  r2.xy = r2.xy * float2(2,2) + float2(-1,-1);\n";
  if (text.find(ndc) == std::string::npos) return "";
  return text.replace(text.find(ndc), ndc.size(), "  r2.xy = v0.xy;\n");
}

class DeferredRender : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    context_ = VulkanContext::create(&error);
    ASSERT_TRUE(context_) << error;
    TranspileOptions options;
    gbufferVert_ = compileOriginal("gbuffer.vert", kGBufferVert, options);
    albedoFrag_ = compileOriginal("gbuffer_albedo.frag", kGBufferAlbedoFrag, options);
    normalFrag_ = compileOriginal("gbuffer_normal.frag", kGBufferNormalFrag, options);
    fullScreenVert_ = compileOriginal("deferred_light.vert", kFullScreenVert, options);
    vertices_ = sceneVertices(scene());
    vertexCount_ = static_cast<uint32_t>(scene().size() * 6);
  }

  // The scene's camera block (kGBufferVert's) for one eye: its stereo projection and the view.
  static std::vector<uint8_t> cameraOf(double eye) {
    std::vector<uint8_t> camera;
    auto proj = toFloat(projection(eye)), viewMatrix = toFloat(view());
    append(camera, proj.data(), 16);
    append(camera, viewMatrix.data(), 16);
    return camera;
  }

  // The G-buffer of one eye, rendered with that eye's stereo projection.
  GBuffer renderGBuffer(double eye) {
    GBuffer g;
    const std::vector<uint8_t> camera = cameraOf(eye);
    auto pass = [&](const std::vector<uint32_t>& frag, bool readDepth) {
      RenderRequest request;
      request.width = request.height = kSize;
      request.clearColor[0] = request.clearColor[1] = request.clearColor[2] = 0.5f;  // normal (0,0,0)
      request.readDepth = readDepth;
      Draw draw;
      draw.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, gbufferVert_, "main"},
                              {VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main"}};
      draw.pipeline.vertices = vertices_;
      draw.pipeline.vertexCount = vertexCount_;
      draw.pipeline.uniformBuffers = {{0, 0, camera}};
      request.draws = {draw};
      RenderResult r = context_->render(request);
      EXPECT_TRUE(r.ok()) << r.error;
      return r;
    };
    RenderResult albedo = pass(albedoFrag_, true), normal = pass(normalFrag_, false);
    auto texture = [&](uint32_t binding, const RenderResult& r) {
      SampledTexture t{1, binding, kSize, kSize, std::vector<float>(size_t(kSize) * kSize * 4)};
      for (size_t i = 0; i < t.rgba.size(); ++i) t.rgba[i] = r.pixels[i] / 255.0f;
      return t;
    };
    g.albedo = texture(0, albedo);
    g.normal = texture(1, normal);
    g.depthValues = albedo.depth;
    g.depth = SampledTexture{1, 2, kSize, kSize, std::vector<float>(size_t(kSize) * kSize * 4, 0.0f)};
    for (size_t i = 0; i < g.depthValues.size(); ++i) g.depth.rgba[4 * i] = g.depthValues[i];
    return g;
  }

  // The lighting pass with `inverseViewProj`; with `eyeParams` the shader is the transpiled one.
  RenderResult renderLighting(const GBuffer& g, const std::vector<uint32_t>& frag, const Mat4& inverseViewProj,
                              const Transpiled* eyeParams, double eye, DumpFeed dump = {}) {
    std::vector<uint8_t> frame;
    const Mat4 matrix = dump.uvSpace       ? multiply(inverseViewProj, uvToNdc())
                        : dump.pixelSpace ? multiply(inverseViewProj, pixelToNdc())
                                          : inverseViewProj;
    Mat4 uploaded = matrix;
    if (dump.rows)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) uploaded[c * 4 + r] = matrix[r * 4 + c];
    auto inv = toFloat(uploaded);
    const float viewport[4] = {float(kSize), float(kSize), 1.0f / kSize, 1.0f / kSize};
    float light[8] = {0.8f, 1.5f, -5.0f, 22.0f, 1.0f, 0.95f, 0.85f, 0.0f};
    if (dump.row5) std::copy(dump.row5->begin(), dump.row5->end(), light);
    append(frame, inv.data(), 16);
    append(frame, viewport, 4);
    append(frame, light, 8);
    // The matrix the inverse undoes, after the rest (kViewRayFrag with REPROJECT re-projects with it).
    auto forward = toFloat(inverse(inverseViewProj));
    append(frame, forward.data(), 16);
    RenderRequest request;
    request.width = request.height = kSize;
    Draw draw;
    draw.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, fullScreenVert_, "main"},
                            {VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main"}};
    draw.pipeline.vertexCount = 3;
    draw.pipeline.uniformBuffers = {{0, 0, frame}};
    if (eyeParams) {
      const float params[4] = {float(eye), kSeparation, kConvergence, 0.0f};
      std::vector<uint8_t> bytes;
      append(bytes, params, 4);
      draw.pipeline.uniformBuffers.push_back({eyeParams->eyeSet, eyeParams->eyeBinding, bytes});
    }
    draw.pipeline.textures = {g.albedo, g.normal, g.depth};
    if (dump.uvSpace || dump.sampler) {
      SampledTexture sampler{1, 3, 1, 1, {0, 0, 0, 0}};
      sampler.type = VK_DESCRIPTOR_TYPE_SAMPLER;
      draw.pipeline.textures.push_back(sampler);
    }
    if (dump.stereoParams)
      draw.pipeline.textures.push_back(
          SampledTexture{0, 125, 1, 1, {float(eye * kSeparation), kConvergence, float(eye), 0.0f}});
    draw.depthTest = false;
    draw.depthWrite = false;
    if (dump.forward) {
      draw.pipeline.stages[0] = {VK_SHADER_STAGE_VERTEX_BIT, gbufferVert_, "main"};
      draw.pipeline.vertices = vertices_;
      draw.pipeline.vertexCount = vertexCount_;
      draw.pipeline.uniformBuffers[0] = {0, 1, frame};
      draw.pipeline.uniformBuffers.push_back({0, 0, cameraOf(eye)});
      draw.depthTest = draw.depthWrite = true;
    }
    request.draws = {draw};
    RenderResult r = context_->render(request);
    EXPECT_TRUE(r.ok()) << r.error;
    return r;
  }

  // `dump`: the shader is a 3Dmigoto dump, converted as text with --eye-source 3dmigoto.
  void checkRebuiltPositions(const char* name, const char* text, const char* tag, const DumpFeed* dump = nullptr);
  // The view-ray check: the rebuilt view-space point of fix and mono baseline against the exact one.
  void checkViewRay(const char* name, const char* text, const char* tag, const DumpFeed* dump = nullptr);
  void checkLitImage(const char* name, const char* text, const char* tag, const std::string& pngPrefix);
  // The screen-to-world check: truth, fix and baseline of kDumpScreenToWorld against the exact point.
  // `uvSpace`: the dump reads the pixel's UV, the one the depth is sampled at, and the map takes
  // (u z, v z, z, 1).
  // `pixelSpace`: it reads the pixel position as it is (the depth loaded there), the map takes
  // (p.x z, p.y z, z, 1), and the fix computes the pixel's half-width from the map.
  // `basis`: the dump is the basis form (its report's construct), the map's w row unread.
  void checkScreenToWorld(const char* name, const char* text, const char* tag, bool uvSpace = false,
                          bool pixelSpace = false, bool basis = false);
  // checkScreenToWorld behind `vertex` (GLSL, named `vertexName`) instead of the harness's own
  // full-screen vertex stage, for a dump that reads what that stage hands on.
  void checkScreenToWorldAfter(const char* vertexName, const char* vertex, const char* name, const char* text,
                               const char* tag) {
    const std::vector<uint32_t> fullScreen = fullScreenVert_;
    fullScreenVert_ = compileOriginal(vertexName, vertex, TranspileOptions{});
    checkScreenToWorld(name, text, tag);
    fullScreenVert_ = fullScreen;
  }
  // The camera check: the view vector to the rebuilt position from this eye's camera.
  // `screenToWorldForm`: the dump rebuilds through a screen-to-world map (linear depth); `fromCamera`:
  // its vector is p - c, not c - p.
  // `pixelSpace` (the (ndc, depth, 1) form): it reads the pixel position as it is through the matrix
  // from pixels, the fix computing the pixel's half-width from it.
  void checkViewVector(const char* name, const char* text, const char* tag, bool screenToWorldForm = false,
                       bool fromCamera = false, bool pixelSpace = false);

  // The re-projection check: the dump `text` writes the NDC x its corrected point lands at, projected
  // back through cb0[7..10], minus the pixel's; `viewSpace`: it rebuilds a view-space point from the
  // linear depth (the inverse projection fed), else a world-space one from the depth buffer.
  void checkDumpReprojection(const char* name, const std::string& text, bool viewSpace, const char* tag);
  // The same for a GLSL shader, through the SPIR-V route and the spliced text (its re-projection
  // through `wrapped`), and that text with the wrapper taken out (the rebuild alone corrected).
  void checkReprojectionLandsOnItsPixel(const char* name, const char* text, const TranspileOptions& options,
                                        const std::string& wrapped, bool viewSpace, const char* tag);

  bool splicedText_ = false;  // the fix through the GLSL splice's text (compileTranspiled)
  std::unique_ptr<VulkanContext> context_;
  std::vector<uint32_t> gbufferVert_, albedoFrag_, normalFrag_, fullScreenVert_;
  VertexBuffer vertices_;
  uint32_t vertexCount_ = 0;
};

// Check 1 for the lighting shader `text` (GLSL or HLSL, by the extension of `name`).
void DeferredRender::checkRebuiltPositions(const char* name, const char* text, const char* tag, const DumpFeed* dump) {
  const Mat4 viewMatrix = view();
  const Mat4 monoInverse = inverse(multiply(projection(0), viewMatrix));
  for (double eye : {-1.0, 1.0}) {
    GBuffer g = renderGBuffer(eye);
    const Mat4 stereoInverse = inverse(multiply(projection(eye), viewMatrix));
    // What the GPU multiplies with: the matrices as uploaded (rounded to fp32).
    const Mat4 stereoInverseF = toDouble(toFloat(stereoInverse)), monoInverseF = toDouble(toFloat(monoInverse));
    std::array<RenderResult, 3> truth, fixedPosition, baseline;
    for (int component = 0; component < 3; ++component) {
      TranspileOptions options;
      options.defines = {"POSITION_COMPONENT=" + std::to_string(component)};
      auto original = compileOriginal(name, text, options);
      if (dump) {
        DumpFeed mono = *dump, stereo = *dump;
        mono.stereoParams = false;
        stereo.stereoParams = true;
        std::vector<uint32_t> fixedDump = compileDumpFixed(name, text, options);
        truth[component] = renderLighting(g, original, stereoInverse, nullptr, eye, mono);
        fixedPosition[component] = renderLighting(g, fixedDump, monoInverse, nullptr, eye, stereo);
        baseline[component] = renderLighting(g, original, monoInverse, nullptr, eye, mono);
      } else {
        Transpiled transpiled = compileTranspiled(name, text, options, splicedText_);
        truth[component] = renderLighting(g, original, stereoInverse, nullptr, eye);
        fixedPosition[component] = renderLighting(g, transpiled.spirv, monoInverse, &transpiled, eye);
        baseline[component] = renderLighting(g, original, monoInverse, nullptr, eye);
      }
      ASSERT_TRUE(truth[component].ok() && fixedPosition[component].ok() && baseline[component].ok());
    }
    double worstTruth = 0, worstFix = 0, maxFixVsTruth = 0, maxFixError = 0, maxBaselineError = 0;
    size_t pixels = 0, outside = 0, baselineOutside = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        size_t i = size_t(y) * kSize + x;
        if (g.depthValues[i] >= 1.0f) continue;  // background: nothing rebuilt
        ++pixels;
        std::array<double, 4> v = {(x + 0.5) / kSize * 2 - 1, (y + 0.5) / kSize * 2 - 1, g.depthValues[i], 1.0};
        const std::array<double, 4> exact = times(stereoInverse, v);
        std::array<double, 3> truthBound, fixBound;
        if (dump && dump->pixelSpace) {  // the pixel position as it is, by the matrix from pixels
          const std::array<double, 4> pixel = {x + 0.5, y + 0.5, g.depthValues[i], 1.0};
          const Mat4 stereoF = toDouble(toFloat(multiply(stereoInverse, pixelToNdc())));
          const Mat4 monoF = toDouble(toFloat(multiply(monoInverse, pixelToNdc())));
          // The fix's column is the matrix's times the half-width it computes from the matrix.
          const MatrixHalfWidth h = matrixHalfWidth(monoF);
          truthBound = positionBound(stereoF, pixel, false, eye * kSeparation, kConvergence);
          fixBound = positionBound(monoF, pixel, true, eye * kSeparation, kConvergence, kSize / 2.0,
                                   std::abs(h.value - kSize / 2.0) + h.bound);
        } else if (dump && dump->uvSpace) {  // the shader multiplies the UV by the matrix from UV space
          const std::array<double, 4> uv = {(x + 0.5) / kSize, (y + 0.5) / kSize, g.depthValues[i], 1.0};
          truthBound = positionBound(toDouble(toFloat(multiply(stereoInverse, uvToNdc()))), uv, false, eye * kSeparation,
                                     kConvergence);
          fixBound = positionBound(toDouble(toFloat(multiply(monoInverse, uvToNdc()))), uv, true, eye * kSeparation,
                                   kConvergence, 0.5);
        } else {
          truthBound = positionBound(stereoInverseF, v, false, eye * kSeparation, kConvergence);
          fixBound = positionBound(monoInverseF, v, true, eye * kSeparation, kConvergence);
        }
        bool baselineWrong = false;
        for (int c = 0; c < 3; ++c) {
          double p = exact[c] / exact[3];
          double truthError = std::abs(bitsAt(truth[c], i) - p), fixError = std::abs(bitsAt(fixedPosition[c], i) - p);
          worstTruth = std::max(worstTruth, truthError / truthBound[c]);
          worstFix = std::max(worstFix, fixError / fixBound[c]);
          maxFixVsTruth = std::max(maxFixVsTruth, std::abs(bitsAt(fixedPosition[c], i) - bitsAt(truth[c], i)));
          maxFixError = std::max(maxFixError, fixError);
          double baselineError = std::abs(bitsAt(baseline[c], i) - p);
          maxBaselineError = std::max(maxBaselineError, baselineError);
          baselineWrong |= baselineError > truthBound[c];
          outside += truthError > truthBound[c] || fixError > fixBound[c];
        }
        baselineOutside += baselineWrong;
      }
    std::cout << std::setprecision(3) << "[" << tag << "] eye " << eye << ": world position over " << pixels
              << " pixels, error / first-order rounding bound: truth " << worstTruth << ", fix " << worstFix
              << "; max |p - p_exact|: fix " << maxFixError << ", mono baseline " << maxBaselineError
              << " world units; max |fix - truth| " << maxFixVsTruth << "; mono baseline beyond rounding at "
              << baselineOutside << " pixels\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2) << "the scene should cover most of the image";
    EXPECT_EQ(outside, 0u) << "eye " << eye << ": a rebuilt position is further from the exact one than rounding allows";
    // The mono inverse misplaces points by S*|w - C|/p00 along the camera's x axis: wrong beyond
    // rounding wherever the surface is not at the convergence distance, i.e. almost everywhere.
    EXPECT_GT(baselineOutside, pixels * 9 / 10) << "eye " << eye << ": the mono baseline should be wrong";
  }
}

// Check 2 for the lighting shader `text`; PNGs named `<pngPrefix>_{left,right}_{truth,fix,mono}.png`.
void DeferredRender::checkLitImage(const char* name, const char* text, const char* tag, const std::string& pngPrefix) {
  TranspileOptions options;
  auto original = compileOriginal(name, text, options);
  Transpiled transpiled = compileTranspiled(name, text, options);
  const Mat4 viewMatrix = view();
  const Mat4 monoInverse = inverse(multiply(projection(0), viewMatrix));

  std::array<RenderResult, 2> fixedImages;
  for (int e = 0; e < 2; ++e) {
    double eye = e == 0 ? -1.0 : 1.0;
    const char* side = e == 0 ? "left" : "right";
    GBuffer g = renderGBuffer(eye);
    RenderResult truth = renderLighting(g, original, inverse(multiply(projection(eye), viewMatrix)), nullptr, eye);
    RenderResult fixed = renderLighting(g, transpiled.spirv, monoInverse, &transpiled, eye);
    RenderResult baseline = renderLighting(g, original, monoInverse, nullptr, eye);
    ASSERT_TRUE(truth.ok() && fixed.ok() && baseline.ok());
    ImageError fixError = compare(truth, fixed), baselineError = compare(truth, baseline);
    std::cout << std::setprecision(4) << "[" << tag << "] eye " << eye << " (" << side << "): fix PSNR "
              << psnr(fixError.mse) << " dB, max diff " << fixError.maxDifference << " (" << fixError.differing
              << " channels differ); mono baseline PSNR " << psnr(baselineError.mse) << " dB, max diff "
              << baselineError.maxDifference << " (" << baselineError.differing << " channels differ) of "
              << 3 * kSize * kSize << "\n";
    // The fix's position is within rounding of the truth (test above), far below what moves a colour
    // by 1/255 here: only the final 8-bit rounding can tell them apart, by one level.
    EXPECT_LE(fixError.maxDifference, 1) << side;
    // The mono inverse puts every pixel's position off by up to S*|w - C|/p00 world units.
    EXPECT_GT(baselineError.maxDifference, 8) << side;
    EXPECT_LT(psnr(baselineError.mse), psnr(fixError.mse) - 20.0) << side;

    std::string prefix = std::string(IMAGE_OUT_DIR) + "/" + pngPrefix + "_" + side;
    EXPECT_TRUE(writePng(prefix + "_truth.png", kSize, kSize, truth.pixels.data()));
    EXPECT_TRUE(writePng(prefix + "_fix.png", kSize, kSize, fixed.pixels.data()));
    EXPECT_TRUE(writePng(prefix + "_mono.png", kSize, kSize, baseline.pixels.data()));
    fixedImages[e] = std::move(fixed);
  }
  std::vector<uint8_t> anaglyph = harness::anaglyph(fixedImages[0].pixels, fixedImages[1].pixels, size_t(kSize) * kSize);
  EXPECT_TRUE(writePng(std::string(IMAGE_OUT_DIR) + "/" + pngPrefix + "_anaglyph.png", kSize, kSize, anaglyph.data()));
  std::cout << "[" << tag << "] wrote " IMAGE_OUT_DIR "/" << pngPrefix << "_{left,right}_{truth,fix,mono}.png, "
            << pngPrefix << "_anaglyph.png\n";
}

TEST_F(DeferredRender, RebuiltPositionWithinRoundingOfTheTruePosition) {
  checkRebuiltPositions("deferred_light.frag", kLightingFrag, "deferred");
}

// The same check with the fix spliced into the shader's own GLSL text: the product wrapped in
// stereoshift_unproject_frame_invViewProj(), the rest as written, compiled as a driver would.
TEST_F(DeferredRender, SplicedGlslTextWithinRoundingOfTheTruePosition) {
  splicedText_ = true;
  checkRebuiltPositions("deferred_light.frag", kLightingFrag, "deferred spliced");
}

TEST_F(DeferredRender, LitImageMatchesTruthWithTheFixNotWithTheMonoInverse) {
  checkLitImage("deferred_light.frag", kLightingFrag, "deferred", "deferred");
}

// The same two checks with the HLSL lighting shader: truth = the original HLSL (glslang's HLSL front
// end, compileToSpirv) with the true per-eye inverse, fix = stereoshift's SPIR-V for it with the mono
// inverse and the eye parameters, baseline = the original with the mono inverse. Same bounds as the
// GLSL shader: positions of truth and fix within positionBound() of the exact position and the mono
// baseline beyond it at > 90 % of the pixels; lit image: fix max diff <= 1 level, baseline max
// diff > 8 levels and PSNR more than 20 dB below the fix's.
TEST_F(DeferredRender, HlslLightingShaderFixedByExecution) {
  // The fix is really in the transpiled module (not a copy of the original that happens to pass).
  Transpiled transpiled = compileTranspiled("deferred_light.frag.hlsl", kLightingHlsl, TranspileOptions{});
  const auto& pass = transpiled.report["passes"]["deferred-unprojection"];
  EXPECT_EQ(pass.value("result", std::string()), "changed") << transpiled.report.dump(2);
  EXPECT_TRUE(pass.contains("fixed") && !pass["fixed"].empty()) << pass.dump(2);
  EXPECT_FALSE(pass.contains("left_alone")) << pass.dump(2);
  checkRebuiltPositions("deferred_light.frag.hlsl", kLightingHlsl, "deferred hlsl");
  checkLitImage("deferred_light.frag.hlsl", kLightingHlsl, "deferred hlsl", "deferred_hlsl");
}

// The HLSL lighting shader with its fix spliced into its own text (`mul(InvViewProj, ...)` wrapped in
// stereoshift_unproject_InvViewProj(), the cbuffer beside it), compiled as a driver would.
TEST_F(DeferredRender, SplicedHlslTextWithinRoundingOfTheTruePosition) {
  splicedText_ = true;
  checkRebuiltPositions("deferred_light.frag.hlsl", kLightingHlsl, "deferred hlsl spliced");
}

// The dump-style lighting shaders (kDumpMadLighting, kDumpDp4Lighting), converted as text with
// --eye-source 3dmigoto (the correction after the statement completing q, 3Dmigoto's StereoParams
// at t125 read for the eye), with the same scene, matrices and bounds as the GLSL and HLSL shaders:
// positions of truth (the original dump with the true per-eye inverse) and fix (the converted dump
// with the mono inverse and StereoParams) within positionBound() of the exact position, the mono
// baseline beyond it at > 90 % of the pixels.
TEST_F(DeferredRender, DumpStyleMadChainFixedInItsTextByExecution) {
  DumpFeed columns{false, false};
  checkRebuiltPositions("0a1b2c3d4e5f6071-ps_replace.txt", kDumpMadLighting.c_str(), "dump mad", &columns);
}

// A sky's early out between the depth read and the rebuild (`if (r1.x >= 1) discard;`, then the
// `mad` chain): the register copy still follows every register through the branch, and the text
// carries the correction past it (the branch writes no register).
TEST_F(DeferredRender, DumpStyleRebuildAfterASkyEarlyOutFixedInItsTextByExecution) {
  std::string text = kDumpMadLighting;
  const std::string chain = "  r3.xyzw = cb0[1].xyzw * r2.yyyy;\n";
  ASSERT_NE(text.find(chain), std::string::npos);
  text.insert(text.find(chain), "  r0.w = cmp(r1.x >= 1.000000);\n  if (r0.w != 0) discard;\n");
  DumpFeed columns{false, false};
  checkRebuiltPositions("0a1b2c3d4e5f6072-ps_replace.txt", text.c_str(), "dump mad after a sky early out", &columns);
}

// The named matrix (namedMatrixDump): the correction reads InvViewProj's elements by name
// (`InvViewProj[i].x`, HLSL's row i, column 0: the column of NDC x).
TEST_F(DeferredRender, DumpStyleNamedMatrixFixedInItsTextByExecution) {
  const std::string text = namedMatrixDump();
  ASSERT_EQ(text.find("cb0["), std::string::npos) << text;
  DumpFeed columns{false, false};
  checkRebuiltPositions("3a4b5c6d7e8f9012-ps_replace.txt", text.c_str(), "dump named matrix", &columns);
}

// The screen-to-world matrix of an inverse view-projection: that inverse times the map from
// (X, Y, Z, 1) = (ndc.x * z, ndc.y * z, z, 1) to clip space (clip.z = -p22 * z + p32, clip.w = z).
Mat4 screenToWorld(const Mat4& inverseViewProj, const Mat4& mono) {
  Mat4 toClip{};
  toClip[0] = toClip[5] = 1.0;
  toClip[10] = -mono[10];
  toClip[11] = 1.0;
  toClip[14] = mono[14];
  return multiply(inverseViewProj, toClip);
}

// The G-buffer with its depth made linear (the positive view depth z, in double from the Vulkan
// depth, stored as fp32), as a screen-to-world shader reads it.
GBuffer linearDepth(const GBuffer& g, const Mat4& mono) {
  GBuffer linear = g;
  for (size_t i = 0; i < g.depthValues.size(); ++i)
    linear.depth.rgba[4 * i] = g.depthValues[i] >= 1.0f ? 0.0f : float(mono[14] / (g.depthValues[i] + mono[10]));
  return linear;
}

// The screen-to-world form: per eye, the G-buffer's depth of that eye made linear (the positive view
// depth z, in double from the Vulkan depth, stored as fp32), the dump run with ScreenToWorld = the
// inverse view-projection times the map from (ndc * z, z, 1) to clip space: truth with the eye's own
// matrix, fix (converted, StereoParams) and baseline with the mono one. The exact position is the
// eye's exact matrix applied in double to the fp32 inputs; truth and fix must be within
// screenToWorldBound() of it, the baseline beyond the truth's bound at more than 90 % of the pixels.
void DeferredRender::checkScreenToWorld(const char* name, const char* text, const char* tag, bool uvSpace,
                                        bool pixelSpace, bool basis) {
  const Mat4 mono = projection(0), viewMatrix = view();
  // From UV space: (u z, v z, z, 1) to (ndc.x z, ndc.y z, z, 1), ndc = 2 uv - 1; from pixels likewise,
  // ndc = 2 p / size - 1.
  const Mat4 fromUv = {2, 0, 0, 0, 0, 2, 0, 0, -1, -1, 1, 0, 0, 0, 0, 1}, identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const Mat4 fromPixels = {2.0 / kSize, 0, 0, 0, 0, 2.0 / kSize, 0, 0, -1, -1, 1, 0, 0, 0, 0, 1};
  const Mat4& screenMap = uvSpace ? fromUv : pixelSpace ? fromPixels : identity;
  const Mat4 monoMatrix = multiply(screenToWorld(inverse(multiply(mono, viewMatrix)), mono), screenMap);
  for (double eye : {-1.0, 1.0}) {
    GBuffer g = renderGBuffer(eye);
    const GBuffer linear = linearDepth(g, mono);
    const Mat4 stereoMatrix = multiply(screenToWorld(inverse(multiply(projection(eye), viewMatrix)), mono), screenMap);
    const Mat4 stereoF = toDouble(toFloat(stereoMatrix)), monoF = toDouble(toFloat(monoMatrix));
    const MatrixHalfWidth halfWidth = affineMapHalfWidth(monoF);
    std::array<RenderResult, 3> truth, fixedPosition, baseline;
    for (int component = 0; component < 3; ++component) {
      TranspileOptions options;
      options.defines = {"POSITION_COMPONENT=" + std::to_string(component)};
      auto original = compileOriginal(name, text, options);
      nlohmann::json pass;
      std::vector<uint32_t> fixedDump = compileDumpFixed(name, text, options, &pass);
      EXPECT_EQ(pass["fixed"][0].value("construct", ""),
                basis        ? "basis vectors in cbuffer rows: (bx * x + by * y + bz) * depth"
                : pixelSpace ? "matrix in cbuffer rows * (screen * depth, depth, 1)"
                             : "matrix in cbuffer rows * (ndc * depth, depth, 1)")
          << pass.dump(2);
      DumpFeed monoFeed{false, false}, stereoFeed{false, true};
      monoFeed.sampler = stereoFeed.sampler = uvSpace;
      truth[component] = renderLighting(linear, original, stereoMatrix, nullptr, eye, monoFeed);
      fixedPosition[component] = renderLighting(linear, fixedDump, monoMatrix, nullptr, eye, stereoFeed);
      baseline[component] = renderLighting(linear, original, monoMatrix, nullptr, eye, monoFeed);
      ASSERT_TRUE(truth[component].ok() && fixedPosition[component].ok() && baseline[component].ok());
    }
    double worstTruth = 0, worstFix = 0;
    size_t pixels = 0, outside = 0, baselineOutside = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        size_t i = size_t(y) * kSize + x;
        if (g.depthValues[i] >= 1.0f) continue;
        ++pixels;
        // The pixel's coordinates as the shader reads them: NDC, or the UV.
        const double nx = uvSpace ? (x + 0.5) / kSize : pixelSpace ? x + 0.5 : (x + 0.5) / kSize * 2 - 1;
        const double ny = uvSpace ? (y + 0.5) / kSize : pixelSpace ? y + 0.5 : (y + 0.5) / kSize * 2 - 1;
        const double z = linear.depth.rgba[4 * i];
        const std::array<double, 4> v = {nx * z, ny * z, z, 1.0};
        const std::array<double, 4> exact = times(stereoMatrix, v);
        auto truthBound = screenToWorldBound(stereoF, nx, ny, z, false, 0.0, kConvergence);
        auto fixBound = pixelSpace ? screenToWorldBound(monoF, nx, ny, z, true, eye * kSeparation, kConvergence, kSize / 2.0,
                                                        std::abs(halfWidth.value - kSize / 2.0) + halfWidth.bound)
                                   : screenToWorldBound(monoF, nx, ny, z, true, eye * kSeparation, kConvergence,
                                                        uvSpace ? 0.5 : 1.0);
        bool baselineWrong = false;
        for (int c = 0; c < 3; ++c) {
          const double p = exact[c] / exact[3];
          const double truthError = std::abs(bitsAt(truth[c], i) - p), fixError = std::abs(bitsAt(fixedPosition[c], i) - p);
          worstTruth = std::max(worstTruth, truthError / truthBound[c]);
          worstFix = std::max(worstFix, fixError / fixBound[c]);
          outside += truthError > truthBound[c] || fixError > fixBound[c];
          baselineWrong |= std::abs(bitsAt(baseline[c], i) - p) > truthBound[c];
        }
        baselineOutside += baselineWrong;
      }
    std::cout << std::setprecision(3) << "[" << tag << "] eye " << eye << ": world position over " << pixels
              << " pixels, error / first-order rounding bound: truth " << worstTruth << ", fix " << worstFix
              << "; mono baseline beyond rounding at " << baselineOutside << " pixels\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2);
    EXPECT_EQ(outside, 0u) << "eye " << eye << ": a rebuilt position is further from the exact one than rounding allows";
    EXPECT_GT(baselineOutside, pixels * 9 / 10) << "eye " << eye << ": the mono baseline should be wrong";
  }
}

// The view vector from the camera to the rebuilt position: the converted dump (position corrected,
// and the camera made this eye's where cb0[5] is the camera the matrix shows) against the exact
// normalize(C_eye - p), with C_eye the projection centre of the eye's exact stereo view-projection
// (computed here on its own, not from the fix's formula). Bound, first order: the rebuilt position's
// rounding bound (positionBound) and the camera's (4u of |C| + |the offset|), over |C_eye - p|, twice
// (a normalized vector moves by at most twice the relative change of the vector), plus 8u for the
// normalization. The position-only fix (the camera block removed) must be beyond the bound at more
// than 90 % of the pixels: its highlight is the mono camera's. With the light's position in cb0[5]
// instead (not the camera the matrix shows) the camera block must leave the vector as it is.
void DeferredRender::checkViewVector(const char* name, const char* text, const char* tag, bool screenToWorldForm,
                                     bool fromCamera, bool pixelSpace) {
  ASSERT_FALSE(screenToWorldForm && pixelSpace) << "the pixel-space view vector check is the matrix form's";
  const Mat4 viewMatrix = view(), mono = projection(0);
  const Mat4 monoInverse = inverse(multiply(mono, viewMatrix));
  // The matrix the dump is fed: the inverse view-projection, or its screen-to-world form (which reads
  // the depth made linear); its column of x is the same.
  const Mat4 monoMatrix = screenToWorldForm ? screenToWorld(monoInverse, mono) : monoInverse;
  const Mat4 inverseView = inverse(viewMatrix);
  const std::array<float, 4> camera = {float(inverseView[12]), float(inverseView[13]), float(inverseView[14]), 0.0f};
  const double u = kUnitRoundoff;
  for (double eye : {-1.0, 1.0}) {
    const GBuffer rendered = renderGBuffer(eye);
    const GBuffer g = screenToWorldForm ? linearDepth(rendered, mono) : rendered;
    const Mat4 stereoInverse = inverse(multiply(projection(eye), viewMatrix));
    // The eye's projection centre: the world point whose stereo clip coordinates are (0, 0, p32, 0).
    const Mat4 stereo = projection(eye);
    std::array<double, 4> centre{};
    for (int r = 0; r < 4; ++r) centre[r] = stereoInverse[2 * 4 + r] * stereo[14];
    const std::array<double, 3> eyeCamera = {centre[0] / centre[3], centre[1] / centre[3], centre[2] / centre[3]};
    std::array<RenderResult, 3> fixedView, positionOnly, lightKept;
    for (int component = 0; component < 3; ++component) {
      TranspileOptions options;
      options.defines = {"VIEW_COMPONENT=" + std::to_string(component)};
      TranspileResult r = transpile(SourceFile{name, text}, dumpConversion(options));
      ASSERT_TRUE(r.ok) << r.diagnostics.format();
      ASSERT_EQ(r.report["passes"]["deferred-unprojection"]["fixed"].size(), 2u) << r.report.dump(2);
      EXPECT_EQ(r.report["passes"]["deferred-unprojection"]["fixed"][1].value("construct", ""),
                fromCamera ? "view vector rebuilt position - camera" : "view vector camera - rebuilt position");
      // The same text without the camera block: the position corrected, the camera mono.
      std::string withoutCamera = r.output;
      const size_t from = withoutCamera.find("  // ---- stereoshift: this eye's camera");
      ASSERT_NE(from, std::string::npos) << r.output;
      const std::string end = "// ---- end stereoshift ----\n";
      withoutCamera.erase(from, withoutCamera.find(end, from) + end.size() - from);
      DumpFeed stereoFeed{false, true, camera}, lightFeed{false, true, std::array<float, 4>{0.8f, 1.5f, -5.0f, 22.0f}};
      stereoFeed.pixelSpace = lightFeed.pixelSpace = pixelSpace;  // renderLighting multiplies by pixelToNdc()
      fixedView[component] = renderLighting(g, compileOriginal(name, r.output.c_str(), options), monoMatrix, nullptr, eye, stereoFeed);
      positionOnly[component] =
          renderLighting(g, compileOriginal(name, withoutCamera.c_str(), options), monoMatrix, nullptr, eye, stereoFeed);
      lightKept[component] = renderLighting(g, compileOriginal(name, r.output.c_str(), options), monoMatrix, nullptr, eye, lightFeed);
      RenderResult lightWithout =
          renderLighting(g, compileOriginal(name, withoutCamera.c_str(), options), monoMatrix, nullptr, eye, lightFeed);
      ASSERT_TRUE(fixedView[component].ok() && positionOnly[component].ok() && lightKept[component].ok());
      EXPECT_EQ(lightKept[component].pixels, lightWithout.pixels) << "a light's position must not be moved per eye";
    }
    const Mat4 monoF = toDouble(toFloat(pixelSpace ? multiply(monoMatrix, pixelToNdc()) : monoMatrix));
    double cameraLength = 0, offsetLength = 0;
    for (int c = 0; c < 3; ++c) {
      cameraLength += double(camera[c]) * camera[c];
      offsetLength += std::pow(kSeparation * kConvergence * monoInverse[c], 2);
    }
    // A half-width the fix computes (pixelSpace): the offset off by its relative error, and one more
    // rounding for the product with it.
    const MatrixHalfWidth halfWidth = matrixHalfWidth(monoF);
    const double scaleError = pixelSpace ? std::abs(halfWidth.value - kSize / 2.0) + halfWidth.bound : 0.0;
    const double cameraBound = 4 * u * (std::sqrt(cameraLength) + std::sqrt(offsetLength)) +
                               (pixelSpace ? std::sqrt(offsetLength) * (scaleError / (kSize / 2.0) + u) : 0.0);
    double worst = 0;
    size_t pixels = 0, outside = 0, monoOutside = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        size_t i = size_t(y) * kSize + x;
        if (rendered.depthValues[i] >= 1.0f) continue;
        ++pixels;
        const double nx = (x + 0.5) / kSize * 2 - 1, ny = (y + 0.5) / kSize * 2 - 1;
        // The exact point the pixel shows in this eye, and the fixed rebuild's rounding bound.
        std::array<double, 4> exact;
        std::array<double, 3> positionError;
        if (screenToWorldForm) {
          const double z = g.depth.rgba[4 * i];
          exact = times(stereoInverse, {nx * z, ny * z, z * -mono[10] + mono[14], z});
          positionError = screenToWorldBound(monoF, nx, ny, z, true, eye * kSeparation, kConvergence);
        } else if (pixelSpace) {
          exact = times(stereoInverse, {nx, ny, g.depthValues[i], 1.0});
          positionError = positionBound(monoF, {x + 0.5, y + 0.5, g.depthValues[i], 1.0}, true, eye * kSeparation,
                                        kConvergence, kSize / 2.0, scaleError);
        } else {
          const std::array<double, 4> v = {nx, ny, g.depthValues[i], 1.0};
          exact = times(stereoInverse, v);
          positionError = positionBound(monoF, v, true, eye * kSeparation, kConvergence);
        }
        ViewVector expected = viewVectorTo(eyeCamera, exact, positionError, cameraBound);
        const double bound = expected.bound;
        if (fromCamera)
          for (double& c : expected.direction) c = -c;
        bool monoWrong = false;
        for (int c = 0; c < 3; ++c) {
          const double error = std::abs(bitsAt(fixedView[c], i) - expected.direction[c]);
          worst = std::max(worst, error / bound);
          outside += error > bound;
          monoWrong |= std::abs(bitsAt(positionOnly[c], i) - expected.direction[c]) > bound;
        }
        monoOutside += monoWrong;
      }
    std::cout << std::setprecision(3) << "[" << tag << "] eye " << eye << ": view vector over " << pixels
              << " pixels, error / first-order bound: fix " << worst << "; mono camera beyond it at " << monoOutside
              << " pixels\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2);
    EXPECT_EQ(outside, 0u) << "eye " << eye << ": a view vector is further from this eye's than rounding allows";
    EXPECT_GT(monoOutside, pixels * 9 / 10) << "eye " << eye << ": the mono camera's view vector should be wrong";
  }
}

TEST_F(DeferredRender, DumpStyleViewVectorGetsThisEyesCameraByExecution) {
  checkViewVector("5a6b7c8d9e0f1234-ps_replace.txt", kDumpViewVector.c_str(), "dump view vector");
}

// The view vector from a matrix that takes the pixel position as it is (`r2.xy = v0.xy;`): the
// camera moves by the matrix's column of x times the pixel's half-width, which the camera block
// computes from the matrix as the position's does. Before, the position was corrected and the
// camera left mono.
TEST_F(DeferredRender, DumpStyleViewVectorFromPixelPositionsGetsThisEyesCameraByExecution) {
  std::string text = kDumpViewVector;
  text = withThePixelReadAsItIs(text);
  ASSERT_FALSE(text.empty());
  checkViewVector("5a6b7c8d9e0f1239-ps_replace.txt", text.c_str(), "dump view vector from pixel positions", false, false,
                  true);
}

// The same with the perspective divide written as fxc often compiles it, a reciprocal then a
// product (`r3.w = 1 / r3.w; r2.xyz = r3.xyz * r3.www;`): the camera is found all the same.
TEST_F(DeferredRender, DumpStyleViewVectorThroughAReciprocalGetsThisEyesCameraByExecution) {
  std::string text = kDumpViewVector;
  const std::string divide = "  r2.xyz = r3.xyz / r3.www;\n";
  ASSERT_NE(text.find(divide), std::string::npos);
  text.replace(text.find(divide), divide.size(), "  r3.w = 1 / r3.w;\n  r2.xyz = r3.xyz * r3.www;\n");
  checkViewVector("5a6b7c8d9e0f1235-ps_replace.txt", text.c_str(), "dump view vector, reciprocal");
}

TEST_F(DeferredRender, DumpStyleScreenToWorldFixedInItsTextByExecution) {
  checkScreenToWorld("4a5b6c7d8e9f0123-ps_replace.txt", kDumpScreenToWorld.c_str(), "dump screen to world");
}

// A call between the depth read and the rebuild (`sincos(r0.z, r3.z, r3.w);`: a call writes
// registers only through its arguments, and none of these is the depth's r1.x): the correction that
// reads the depth from its register is placed past it, and still right.
TEST_F(DeferredRender, DumpStyleScreenToWorldPastACallFixedInItsTextByExecution) {
  std::string text = kDumpScreenToWorld;
  const std::string first = "  r2.xy = r2.xy * r1.xx;\n";
  ASSERT_NE(text.find(first), std::string::npos);
  text.insert(text.find(first), "  sincos(r0.z, r3.z, r3.w);\n");
  checkScreenToWorld("4a5b6c7d8e9f0124-ps_replace.txt", text.c_str(), "dump screen to world past a call");
}

// The NDC from an interpolated copy of the clip position divided by its w, a scalar input of its own
// (`r2.xy = v1.xy / v2.xx;`): the w tells no x from y, and the point is corrected all the same.
TEST_F(DeferredRender, DumpStyleScreenToWorldFromAnInterpolatedClipPositionFixedByExecution) {
  std::string text = kDumpScreenToWorldPoint;
  auto replace = [&](const std::string& from, const std::string& to) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  };
  replace("  float4 v0 : SV_POSITION0,\n", "  float4 v0 : SV_POSITION0,\n  float4 v1 : TEXCOORD0,\n  float v2 : TEXCOORD1,\n");
  replace("  r2.xy = v0.xy * cb0[4].zw;\n  r2.xy = r2.xy * float2(2,2) + float2(-1,-1);\n", "  r2.xy = v1.xy / v2.xx;\n");
  checkScreenToWorldAfter("clip_copy.vert", kClipCopyVert, "4a5b6c7d8e9f0125-ps_replace.txt", text.c_str(),
                          "dump screen to world, v1.xy / v2.x");
}

// A full-screen pass that hands its NDC corners on in a texture coordinate (`r2.xy = v1.xy;`, read
// as it is): a texture coordinate may carry NDC, and where the depth is not sampled at it (here it
// is loaded at the pixel) it is taken as such, corrected with the map's own column. (A pixel
// position read as it is never is: ps-deferred-screen-to-world-uv.test.)
TEST_F(DeferredRender, DumpStyleScreenToWorldFromNdcCornersInATexcoordFixedByExecution) {
  std::string text = kDumpScreenToWorldPoint;
  auto replace = [&](const std::string& from, const std::string& to) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  };
  replace("  float4 v0 : SV_POSITION0,\n", "  float4 v0 : SV_POSITION0,\n  float4 v1 : TEXCOORD0,\n");
  replace("  r2.xy = v0.xy * cb0[4].zw;\n  r2.xy = r2.xy * float2(2,2) + float2(-1,-1);\n", "  r2.xy = v1.xy;\n");
  const char* ndcCornersVert = R"(#version 450
layout(location = 0) out vec4 outNdc;
out gl_PerVertex { vec4 gl_Position; };
void main() {
  const vec2 positions[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
  vec2 p = positions[gl_VertexIndex];
  outNdc = vec4(p, 0.0, 0.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)";
  checkScreenToWorldAfter("ndc_corners.vert", ndcCornersVert, "4a5b6c7d8e9f0126-ps_replace.txt", text.c_str(),
                          "dump screen to world, NDC in a texcoord");
}

// The direction from the camera, p - c (as a reflection or a fog ray reads it), in both forms: this
// eye's camera subtracted.
TEST_F(DeferredRender, DumpStyleVectorFromTheCameraGetsThisEyesCameraByExecution) {
  std::string text = kDumpViewVector;
  const std::string toCamera = "  r3.xyz = cb0[5].xyz + -r2.xyz;\n";
  ASSERT_NE(text.find(toCamera), std::string::npos);
  text.replace(text.find(toCamera), toCamera.size(), "  r3.xyz = -cb0[5].xyz + r2.xyz;\n");
  checkViewVector("5a6b7c8d9e0f1237-ps_replace.txt", text.c_str(), "dump vector from the camera", false, true);
  const std::string rebuild = "  r3.xyzw = cb0[1].xyzw * r2.yyyy;\n  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;\n"
                              "  r3.xyzw = r1.xxxx * cb0[2].xyzw + r3.xyzw;\n  r3.xyzw = cb0[3].xyzw + r3.xyzw;\n"
                              "  r2.xyz = r3.xyz / r3.www;\n";
  ASSERT_NE(text.find(rebuild), std::string::npos);
  text.replace(text.find(rebuild), rebuild.size(), kScreenToWorldPointChain);
  checkViewVector("5a6b7c8d9e0f1238-ps_replace.txt", text.c_str(), "dump screen to world vector from the camera", true, true);
}

// A screen-to-world point whose w the shader never reads: x, y and z of the columns alone.
TEST_F(DeferredRender, DumpStyleScreenToWorldPointWithoutWFixedInItsTextByExecution) {
  checkScreenToWorld("4a5b6c7d8e9f0124-ps_replace.txt", kDumpScreenToWorldPoint.c_str(), "dump screen to world point");
}

// The view vector from the camera to that point: the camera the screen-to-world map shows is where
// it sends depth 0 (its translation column), and this eye's is beside it along its column of x.
TEST_F(DeferredRender, DumpStyleScreenToWorldViewVectorGetsThisEyesCameraByExecution) {
  std::string text = kDumpViewVector;
  const std::string rebuild = "  r3.xyzw = cb0[1].xyzw * r2.yyyy;\n  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;\n"
                              "  r3.xyzw = r1.xxxx * cb0[2].xyzw + r3.xyzw;\n  r3.xyzw = cb0[3].xyzw + r3.xyzw;\n"
                              "  r2.xyz = r3.xyz / r3.www;\n";
  ASSERT_NE(text.find(rebuild), std::string::npos);
  text.replace(text.find(rebuild), rebuild.size(), kScreenToWorldPointChain);
  checkViewVector("5a6b7c8d9e0f1236-ps_replace.txt", text.c_str(), "dump screen to world view vector", true);
}

TEST_F(DeferredRender, DumpStyleDp4RowsFixedInItsTextByExecution) {
  DumpFeed rows{true, false};
  checkRebuiltPositions("1a2b3c4d5e6f7081-ps_replace.txt", kDumpDp4Lighting.c_str(), "dump dp4", &rows);
}

// The pixel's UV from the depth texture's own size (`t2.GetDimensions(0, fDest.x, fDest.y,
// fDest.z); r2.xy = v0.xy / fDest.xy;`, resinfo in assembly) instead of a cbuffer's inverse screen
// size: a texture's size is the same for every pixel, like a uniform, so the UV and the NDC made
// from it are the screen's as before (this form went unseen: the size query was opaque).
TEST_F(DeferredRender, DumpStyleUvFromTheTextureSizeFixedInItsTextByExecution) {
  std::string text = kDumpDp4Lighting;
  const std::string uv = "  r2.xy = v0.xy * cb0[4].zw;\n";
  ASSERT_NE(text.find(uv), std::string::npos);
  text.replace(text.find(uv), uv.size(), "  t2.GetDimensions(0, fDest.x, fDest.y, fDest.z);\n  r2.xy = v0.xy / fDest.xy;\n");
  DumpFeed rows{true, false};
  checkRebuiltPositions("1a2b3c4d5e6f7082-ps_replace.txt", text.c_str(), "dump dp4, UV from the texture's size", &rows);
}

// A matrix from pixel positions (Unreal's SVPositionToTranslatedWorld: the inverse view-projection
// times the viewport's inverse): the pixel position goes into the product as the rasterizer hands
// it on (`r2.xy = v0.xy;`), the depth loaded at the pixel. The correction's column is the
// matrix's column of x times the half-width in pixels, which the matrix itself shows (its optical
// axis); the bound counts that computation's rounding (matrixHalfWidth). Before, reported and left
// alone (a coordinate of unknown scale).
TEST_F(DeferredRender, DumpStyleMatrixFromPixelPositionsFixedInItsTextByExecution) {
  std::string text = kDumpDp4Lighting;
  text = withThePixelReadAsItIs(text);
  ASSERT_FALSE(text.empty());
  DumpFeed rows{true, false};
  rows.pixelSpace = true;
  checkRebuiltPositions("1a2b3c4d5e6f7084-ps_replace.txt", text.c_str(), "dump dp4, matrix from pixel positions", &rows);
}

// A forward pass (kDumpForwardFromThePixel) rebuilds the point it shades from its own SV_Position,
// x, y and z read as they are, through the matrix from pixels: drawn over the scene with the eye's
// projection, the converted text (mono matrix, StereoParams) must give the eye's exact point within
// the rounding bound, the original with the mono matrix must not. Before, the fragment's own depth
// was not taken as a depth, and the rebuild went unseen.
TEST_F(DeferredRender, DumpStyleForwardRebuildFromThePixelFixedInItsTextByExecution) {
  DumpFeed forward{false, false};
  forward.pixelSpace = forward.forward = true;
  checkRebuiltPositions("1a2b3c4d5e6f7085-ps_replace.txt", kDumpForwardFromThePixel.c_str(),
                        "forward dump, SV_Position through a matrix from pixels", &forward);
}

// The screen-to-world form from pixel positions: SV_Position's x and y as they are (`r2.xy = v0.xy;`,
// the depth loaded at the pixel) times the linear depth, through a map that takes (p.x z, p.y z, z,
// 1). The correction's column is the map's times the pixel's half-width, which the fix computes from
// the map (the camera is its constant column; the axis is where the point minus the camera is
// orthogonal to its column of x). Before, reported and left alone.
TEST_F(DeferredRender, DumpStyleScreenToWorldFromPixelPositionsFixedInItsTextByExecution) {
  std::string text = kDumpScreenToWorld;
  text = withThePixelReadAsItIs(text);
  ASSERT_FALSE(text.empty());
  checkScreenToWorld("5a6b7c8d9e0f1a2d-ps_replace.txt", text.c_str(), "dump screen-to-world from pixel positions", false,
                     true);
}

// The basis form (CryEngine's `(vWBasisX * x + (vWBasisY * y + vWBasisZ)) * depth + cameraPos`): the
// same screen-to-world map, its columns cb0[0..3] read as basis vectors and the camera, applied in
// another order, a ray first and then the ray times the linear depth. The linear forms see that
// product as one term; the basis recogniser looks into the ray. Before, unseen.
TEST_F(DeferredRender, DumpStyleBasisRayTimesDepthFixedInItsTextByExecution) {
  std::string text = kDumpScreenToWorld;
  const std::string chain = "  r2.xy = r2.xy * r1.xx;\n  r2.z = r1.x;\n  r3.xyzw = cb0[1].xyzw * r2.yyyy;\n"
                            "  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;\n  r3.xyzw = r2.zzzz * cb0[2].xyzw + r3.xyzw;\n"
                            "  r3.xyzw = cb0[3].xyzw + r3.xyzw;\n  r2.xyz = r3.xyz / r3.www;\n";
  ASSERT_NE(text.find(chain), std::string::npos);
  text.replace(text.find(chain), chain.size(),
               "  r3.xyz = cb0[1].xyz * r2.yyy;\n  r3.xyz = r2.xxx * cb0[0].xyz + r3.xyz;\n  r3.xyz = cb0[2].xyz + r3.xyz;\n"
               "  r2.xyz = r3.xyz * r1.xxx + cb0[3].xyz;\n");
  checkScreenToWorld("5a6b7c8d9e0f1a2e-ps_replace.txt", text.c_str(), "dump basis ray times depth", false, false, true);
}

// A dump (kDumpPrologue's) with the depth sampled at the pixel's UV (`v0.xy * cb0[4].zw`, no
// `* 2 - 1`) through a sampler at s3, instead of loaded at the pixel and made NDC; "" if the
// prologue is not there.
std::string withTheDepthSampledAtTheUv(std::string text) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"Texture2D<float4> t2 : register(t2, space1);\n",
            "Texture2D<float4> t2 : register(t2, space1);\nSamplerState s3_s : register(s3, space1);\n"},
           {"  r1.x = t2.Load(r0.xyz).x;\n  r2.xy = v0.xy * cb0[4].zw;\n  r2.xy = r2.xy * float2(2,2) + float2(-1,-1);\n",
            "  r2.xy = v0.xy * cb0[4].zw;\n  r1.x = t2.SampleLevel(s3_s, r2.xy, 0).x;\n"}}) {
    if (text.find(from) == std::string::npos) return "";
    text.replace(text.find(from), from.size(), to);
  }
  return text;
}

// A matrix from UV space (the inverse view-projection times the UV-to-NDC map, as an engine bakes
// it): the pixel's UV (`v0.xy * cb0[4].zw`, no `* 2 - 1`) goes into the product as it is, and the
// depth is sampled at that very UV. That makes it the depth buffer's UV, over [0, 1] where NDC is
// over [-1, 1]: the correction takes half the matrix's column of u, InvM's column of NDC x. (Read
// without the depth sampled there it stays a UV or a pixel position of unknown scale, left alone.)
TEST_F(DeferredRender, DumpStyleMatrixFromUvSpaceFixedInItsTextByExecution) {
  const std::string text = withTheDepthSampledAtTheUv(kDumpDp4Lighting);
  ASSERT_FALSE(text.empty());
  DumpFeed rows{true, false};
  rows.uvSpace = true;
  checkRebuiltPositions("1a2b3c4d5e6f7083-ps_replace.txt", text.c_str(), "dump dp4, matrix from UV space", &rows);
}

// The screen-to-world form from UV space: the pixel's UV (`v0.xy * cb0[4].zw`), the one the linear
// depth is sampled at, times that depth, through a map that takes (u z, v z, z, 1): corrected with
// half the map's column of u. (Before, the product with the screen size was not taken, and the
// same product read as a view ray with 1/P00 = the screen size was "corrected" by 1/width of it.)
TEST_F(DeferredRender, DumpStyleScreenToWorldFromUvSpaceFixedInItsTextByExecution) {
  const std::string text = withTheDepthSampledAtTheUv(kDumpScreenToWorld);
  ASSERT_FALSE(text.empty());
  checkScreenToWorld("5a6b7c8d9e0f1a2c-ps_replace.txt", text.c_str(), "dump screen-to-world from UV space", true);
}

// The view-ray form: per eye, the G-buffer depth drawn with that eye's stereo projection, made
// linear (the positive view depth d = -z_view, in double from the Vulkan depth), read back by
// kViewRayFrag with the mono inverse projection: stereoshift's version with the eye parameters
// (fix) and the original (mono baseline). The exact point is the mono-view-space surface point the
// pixel shows: the stereo inverse projection of (pixel-centre NDC, depth). Measured relative
// errors |p - p_exact| / |p_exact| (max over pixels, lavapipe): fix 1.11e-7 (left eye) and
// 1.15e-7 (right), about one fp32 ulp; mono baseline 0.037 and 0.035. Asserted: the fix within
// kViewRayBound = 5e-7 (four ulps) everywhere; the baseline, off by e*S*(d - C)/p00 in x, beyond
// 1000 times that bound at nine pixels out of ten (it is right only near the convergence depth).
void DeferredRender::checkViewRay(const char* name, const char* text, const char* tag, const DumpFeed* dump) {
  constexpr double kViewRayBound = 5e-7;
  const Mat4 monoInverseProjection = inverse(projection(0));
  const Mat4 mono = projection(0);
  for (double eye : {-1.0, 1.0}) {
    GBuffer g = renderGBuffer(eye);
    const Mat4 stereoInverseProjection = inverse(projection(eye));
    GBuffer linear = g;
    for (size_t i = 0; i < g.depthValues.size(); ++i) {
      double zNdc = g.depthValues[i];
      // Vulkan depth: z_ndc = -p22 - p32 / z_view, so d = -z_view = p32 / (z_ndc + p22).
      linear.depth.rgba[4 * i] = g.depthValues[i] >= 1.0f ? 0.0f : float(mono[14] / (zNdc + mono[10]));
    }
    std::array<RenderResult, 3> fixedPosition, baseline;
    nlohmann::json report;
    for (int component = 0; component < 3; ++component) {
      TranspileOptions options;
      options.defines = {"POSITION_COMPONENT=" + std::to_string(component)};
      auto original = compileOriginal(name, text, options);
      if (dump) {
        DumpFeed mono{dump->rows, false}, stereo{dump->rows, true};
        std::vector<uint32_t> fixedDump = compileDumpFixed(name, text, options, &report);
        fixedPosition[component] = renderLighting(linear, fixedDump, monoInverseProjection, nullptr, eye, stereo);
        baseline[component] = renderLighting(linear, original, monoInverseProjection, nullptr, eye, mono);
      } else {
        Transpiled transpiled = compileTranspiled(name, text, options, splicedText_);
        report = transpiled.report["passes"]["deferred-unprojection"];
        fixedPosition[component] = renderLighting(linear, transpiled.spirv, monoInverseProjection, &transpiled, eye);
        baseline[component] = renderLighting(linear, original, monoInverseProjection, nullptr, eye);
      }
      ASSERT_TRUE(fixedPosition[component].ok() && baseline[component].ok());
    }
    ASSERT_TRUE(report.contains("fixed")) << report.dump(2);
    EXPECT_EQ(report["fixed"][0].value("projection_scale", ""), dump ? "1 / cb0[0].x" : "1 / frame.invProjection[0][0]")
        << report.dump(2);
    double worstFix = 0, worstBaseline = 0;
    size_t pixels = 0, baselineWrong = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        size_t i = size_t(y) * kSize + x;
        if (g.depthValues[i] >= 1.0f) continue;
        ++pixels;
        std::array<double, 4> v = {(x + 0.5) / kSize * 2 - 1, (y + 0.5) / kSize * 2 - 1, g.depthValues[i], 1.0};
        const std::array<double, 4> exact = times(stereoInverseProjection, v);
        double length = 0, fixError = 0, baselineError = 0;
        for (int c = 0; c < 3; ++c) {
          double p = exact[c] / exact[3];
          length += p * p;
          fixError = std::max(fixError, std::abs(bitsAt(fixedPosition[c], i) - p));
          baselineError = std::max(baselineError, std::abs(bitsAt(baseline[c], i) - p));
        }
        length = std::sqrt(length);
        worstFix = std::max(worstFix, fixError / length);
        worstBaseline = std::max(worstBaseline, baselineError / length);
        baselineWrong += baselineError / length > 1000 * kViewRayBound;
      }
    std::cout << std::setprecision(3) << "[" << tag << "] eye " << eye << ": view-space position over " << pixels
              << " pixels, max |p - p_exact| / |p_exact|: fix " << worstFix << ", mono baseline " << worstBaseline
              << "; baseline beyond 1000x the fix bound at " << baselineWrong << " pixels\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2);
    EXPECT_LT(worstFix, kViewRayBound) << "eye " << eye;
    EXPECT_GT(baselineWrong, pixels * 9 / 10) << "eye " << eye << ": the mono baseline should be wrong";
  }
}

TEST_F(DeferredRender, ViewRayPositionWithinBoundOfTheTruePosition) {
  checkViewRay("view_ray.frag", kViewRayFrag, "view ray");
}

// The same check with the fix spliced into the shader's own GLSL text: the assignment's right-hand
// side through stereoshift_view_ray_viewPos(), the text compiled here as a driver would.
TEST_F(DeferredRender, SplicedGlslViewRayWithinBoundOfTheTruePosition) {
  splicedText_ = true;
  checkViewRay("view_ray.frag", kViewRayFrag, "view ray spliced");
}

// A corrected view-ray position re-projected with the mono projection (SSAO's samples, screen-space
// reflections) must land where this eye's image has the point: kViewRayFrag with REPROJECT
// re-projects the pixel's own surface point, which in the eye's image is the pixel itself, and
// writes the NDC x it lands at minus the pixel's. Through the SPIR-V route and the spliced text (the re-projection
// through stereoshift_reproject_frame_projection()) it is 0 within rounding: measured at most
// 2.4e-7 (lavapipe, both eyes, both routes); with the view ray corrected and the re-projection's fix
// taken out of the text, off by e*S*(1 - C/w): beyond 1000 times the bound at 57618 of 63100 pixels
// (left) and 57930 of 63470 (right), right only near the convergence depth.
void DeferredRender::checkReprojectionLandsOnItsPixel(const char* name, const char* text, const TranspileOptions& options,
                                                      const std::string& wrapped, bool viewSpace, const char* tag) {
  constexpr double kBound = 4e-6;  // a few ulps of NDC values near 1, through two matrix products
  const Mat4 mono = projection(0);
  const Mat4 monoInverse = inverse(viewSpace ? mono : multiply(mono, view()));
  Transpiled viaSpirv = compileTranspiled(name, text, options);
  TranspileOptions textOptions = options;
  textOptions.target = TargetLanguage::Auto;
  TranspileResult spliced = transpile(SourceFile{name, text}, textOptions);
  ASSERT_TRUE(spliced.ok) << spliced.diagnostics.format();
  ASSERT_EQ(spliced.report.value("route", std::string()), "glsl-source-splice") << spliced.report.dump(2);
  size_t at = spliced.output.find(wrapped, spliced.output.find("void main"));
  ASSERT_NE(at, std::string::npos) << spliced.output;
  std::string withoutReprojection = spliced.output;
  withoutReprojection.replace(at, wrapped.size(), "(");
  Transpiled viaText = viaSpirv, viaTextUnfixed = viaSpirv;
  viaText.spirv = compileOriginal(name, spliced.output.c_str(), options);
  viaTextUnfixed.spirv = compileOriginal(name, withoutReprojection.c_str(), options);
  for (double eye : {-1.0, 1.0}) {
    GBuffer g = renderGBuffer(eye);
    if (viewSpace) g = linearDepth(g, mono);
    RenderResult a = renderLighting(g, viaSpirv.spirv, monoInverse, &viaSpirv, eye);
    RenderResult b = renderLighting(g, viaText.spirv, monoInverse, &viaText, eye);
    RenderResult c = renderLighting(g, viaTextUnfixed.spirv, monoInverse, &viaTextUnfixed, eye);
    ASSERT_TRUE(a.ok() && b.ok() && c.ok());
    double worstSpirv = 0, worstText = 0;
    size_t pixels = 0, unfixedWrong = 0;
    for (size_t i = 0; i < g.depthValues.size(); ++i) {
      if (g.depthValues[i] >= 1.0f) continue;
      ++pixels;
      worstSpirv = std::max(worstSpirv, std::abs(double(bitsAt(a, i))));
      worstText = std::max(worstText, std::abs(double(bitsAt(b, i))));
      unfixedWrong += std::abs(double(bitsAt(c, i))) > 1000 * kBound;
    }
    std::cout << std::setprecision(3) << "[" << tag << "] eye " << eye << ": max |ndc - pixel| over " << pixels
              << " pixels: SPIR-V " << worstSpirv << ", spliced text " << worstText
              << "; without the re-projection's fix beyond 1000x the bound at " << unfixedWrong << " pixels\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2);
    EXPECT_LT(worstSpirv, kBound) << "eye " << eye;
    EXPECT_LT(worstText, kBound) << "eye " << eye;
    EXPECT_GT(unfixedWrong, pixels * 9 / 10) << "eye " << eye << ": without the re-projection's fix it should be off";
  }
}

TEST_F(DeferredRender, ReprojectedViewRayPositionLandsOnItsPixelInThisEye) {
  TranspileOptions options;
  options.defines = {"REPROJECT"};
  checkReprojectionLandsOnItsPixel("reproject.frag", kViewRayFrag, options, "stereoshift_reproject_frame_projection(", true,
                                   "view ray re-projected");
}

// The matrix form's rebuild re-projected: the world position rebuilt through the inverse
// view-projection (kLightingFrag's), projected back through the view-projection (the frame block's
// last member, which renderLighting() fills with the matrix the inverse undoes) and the depth texture
// read again where it lands (SSAO's or a reflection's step); writes the NDC x it lands at minus the
// pixel's. In this eye's image the pixel's own point is the pixel itself.
const char* kRebuildReprojectedFrag = R"(#version 450
layout(set = 0, binding = 0) uniform FrameUBO {
    mat4 invViewProj;
    vec4 viewportSize;
    vec4 light[2];
    mat4 viewProj;
} frame;
layout(set = 1, binding = 2) uniform sampler2D gDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main()
{
    float depth = texture(gDepth, inUV).r;
    vec2 ndc = gl_FragCoord.xy * frame.viewportSize.zw * 2.0 - 1.0;
    vec4 q = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec3 p = q.xyz / q.w;
    vec4 back = frame.viewProj * vec4(p, 1.0);
    vec2 uv = back.xy / back.w * 0.5 + 0.5;
    if (texture(gDepth, uv).r > 2.0) discard;
    outColor = unpackUnorm4x8(floatBitsToUint(back.x / back.w - ndc.x));
}
)";

// A re-projection of the matrix form's corrected position, read at in the depth texture, gets the
// shift back to this eye's screen (as a view-ray position's does): through the SPIR-V route and the
// spliced text, the pixel's own point lands on the pixel within the view-ray test's bound; with the
// re-projection's fix taken out of the text (the rebuild alone corrected), off by s*(1 - C/w) at
// > 90 % of the pixels.
TEST_F(DeferredRender, ReprojectedRebuiltPositionLandsOnItsPixelInThisEye) {
  Transpiled viaSpirv = compileTranspiled("rebuild_reproject.frag", kRebuildReprojectedFrag, TranspileOptions{});
  const auto& pass = viaSpirv.report["passes"]["deferred-unprojection"];
  ASSERT_EQ(pass["fixed"].size(), 2u) << pass.dump(2);
  EXPECT_EQ(pass["fixed"][1].value("construct", ""), "matrix * rebuilt position, read at in the depth texture");
  checkReprojectionLandsOnItsPixel("rebuild_reproject.frag", kRebuildReprojectedFrag, TranspileOptions{},
                                   "stereoshift_reproject_frame_viewProj(", false, "rebuild re-projected");
}

// The view-ray form as a decompiled dump writes it, one component at a time (kDumpViewRay): the
// converted text's view-space x corrected by s.x*(|depth| - s.y)*|k| after its statement, the same
// bound as the SPIR-V fix of the GLSL shader.
TEST_F(DeferredRender, DumpStyleViewRayComponentsFixedInItsTextByExecution) {
  DumpFeed columns{false, false};
  checkViewRay("2a3b4c5d6e7f8091-ps_replace.txt", kDumpViewRay.c_str(), "dump view ray", &columns);
}

// A full-screen pass's vertex stage that hands on, beside its UV, the ray to each corner's point on
// the far plane in view space, from the frame's inverse projection (Unity's directional lights and
// screen-space shadows): drawn at w = 1, so the driver's cutoff keeps it mono.
const char* kFarPlaneRayVert = R"(#version 450
layout(set = 0, binding = 0) uniform FrameUBO { mat4 invProjection; } frame;
layout(location = 0) out vec4 outUv;
layout(location = 1) out vec3 outRay;
out gl_PerVertex { vec4 gl_Position; };
void main() {
  const vec2 positions[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
  vec2 p = positions[gl_VertexIndex];
  outUv = vec4(p * 0.5 + 0.5, 0.0, 1.0);
  vec4 farPoint = frame.invProjection * vec4(p, 1.0, 1.0);
  outRay = farPoint.xyz / farPoint.w;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Its pixel shader as a decompiled dump: the ray scaled to depth 1 by the far plane's z over its own
// (cb0[5].x, the far plane's view z) and then by the depth over the far distance (the linear
// G-buffer's view depth times cb0[5].y = 1 / far), `r0.x = cb0[5].x / v2.z; r0.xyz = v2.xyz * r0.xxx;
// ... r0.xyz = r1.zzz * r0.xyz;`; writes the view-space point's component POSITION_COMPONENT.
const std::string kDumpFarPlaneRay = R"(// ---- Created with 3Dmigoto v1.3.16 (a test dump written for stereoshift)
cbuffer cb0 : register(b0)
{
  float4 cb0[7];
}

Texture2D<float4> t2 : register(t2, space1);


// 3Dmigoto declarations
#define cmp -
Texture2D<float4> StereoParams : register(t125);


void main(
  float4 v0 : SV_POSITION0,
  float4 v1 : TEXCOORD0,
  float3 v2 : TEXCOORD1,
  out float4 o0 : SV_Target0)
{
  float4 r0,r1;
  uint4 bitmask, uiDest;
  float4 fDest;

  r0.x = cb0[5].x / v2.z;
  r0.xyz = v2.xyz * r0.xxx;
  r1.xy = (int2)v0.xy;
  r1.zw = float2(0,0);
  r1.z = t2.Load(r1.xyz).x;
  r1.z = cb0[5].y * r1.z;
  r0.xyz = r1.zzz * r0.xyz;
  uiDest.x = asuint(r0[POSITION_COMPONENT]);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
}
)";

// The far-plane ray's fix by execution: the view-space point of the fix (the converted dump with
// StereoParams; the ray is the same in both eyes) against the exact point this eye's pixel shows,
// the mono baseline (the original) beyond the bound at > 90 % of the pixels. The fix reads 1/P00 off
// the ray (k = x * ddx(ratio) - ratio), so its bound is the view ray's plus the correction's size
// times k's error: each ratio v2.x / v2.z within kRatioUlps ulps of the largest the triangle's
// vertices carry (3/f: the interpolation's plane equation runs over them, then one divide), x *
// ddx(ratio) twice that times x. With the ray's z not the far plane's (a light volume's ray, cb0[5].x
// doubled here), the converted dump must give the original's bits: it is left as it is.
TEST_F(DeferredRender, DumpStyleFarPlaneRayOfAFullScreenPassFixedByExecution) {
  constexpr double kViewRayBound = 5e-7, kRatioUlps = 8;
  const char* name = "5c6d7e8f90123456-ps_replace.txt";
  const std::vector<uint32_t> fullScreen = fullScreenVert_;
  fullScreenVert_ = compileOriginal("far_plane_ray.vert", kFarPlaneRayVert, TranspileOptions{});
  const Mat4 mono = projection(0), monoInverseProjection = inverse(mono);
  const double f = mono[0], far = mono[14] / (mono[10] + 1.0);  // the far plane's distance
  for (double eye : {-1.0, 1.0}) {
    GBuffer g = renderGBuffer(eye);
    GBuffer linear = g;
    for (size_t i = 0; i < g.depthValues.size(); ++i)
      linear.depth.rgba[4 * i] = g.depthValues[i] >= 1.0f ? 0.0f : float(mono[14] / (double(g.depthValues[i]) + mono[10]));
    const Mat4 stereoInverseProjection = inverse(projection(eye));
    std::array<RenderResult, 3> fixedPosition, baseline, volumeFix, volumeOriginal;
    for (int component = 0; component < 3; ++component) {
      TranspileOptions options;
      options.defines = {"POSITION_COMPONENT=" + std::to_string(component)};
      const auto original = compileOriginal(name, kDumpFarPlaneRay.c_str(), options);
      nlohmann::json report;
      const auto fixedDump = compileDumpFixed(name, kDumpFarPlaneRay.c_str(), options, &report);
      EXPECT_EQ(report["fixed"][0].value("construct", ""), "interpolated ray / its z * depth") << report.dump(2);
      DumpFeed monoFeed{false, false}, stereoFeed{false, true};
      monoFeed.row5 = stereoFeed.row5 = std::array<float, 4>{float(-far), float(1.0 / far), 0.0f, 0.0f};
      fixedPosition[component] = renderLighting(linear, fixedDump, monoInverseProjection, nullptr, eye, stereoFeed);
      baseline[component] = renderLighting(linear, original, monoInverseProjection, nullptr, eye, monoFeed);
      DumpFeed volumeMono = monoFeed, volumeStereo = stereoFeed;
      volumeMono.row5 = volumeStereo.row5 = std::array<float, 4>{float(-2 * far), float(1.0 / far), 0.0f, 0.0f};
      volumeFix[component] = renderLighting(linear, fixedDump, monoInverseProjection, nullptr, eye, volumeStereo);
      volumeOriginal[component] = renderLighting(linear, original, monoInverseProjection, nullptr, eye, volumeMono);
      ASSERT_TRUE(fixedPosition[component].ok() && baseline[component].ok() && volumeFix[component].ok() &&
                  volumeOriginal[component].ok());
    }
    double worstFix = 0, worstBaseline = 0, worstK = 0;
    size_t pixels = 0, outside = 0, baselineWrong = 0, volumeChanged = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const size_t i = size_t(y) * kSize + x;
        if (g.depthValues[i] >= 1.0f) continue;
        ++pixels;
        const std::array<double, 4> v = {(x + 0.5) / kSize * 2 - 1, (y + 0.5) / kSize * 2 - 1, g.depthValues[i], 1.0};
        const std::array<double, 4> exact = times(stereoInverseProjection, v);
        const double depth = -exact[2] / exact[3];
        const double kError = (2 * (x + 0.5) + 1) * kRatioUlps * std::ldexp(3.0 / f, -24);
        const double correctionBound = std::abs(kSeparation * (depth - kConvergence)) * kError;
        double length = 0, fixError = 0, baselineError = 0;
        for (int c = 0; c < 3; ++c) {
          const double p = exact[c] / exact[3];
          length += p * p;
          fixError = std::max(fixError, std::abs(bitsAt(fixedPosition[c], i) - p));
          baselineError = std::max(baselineError, std::abs(bitsAt(baseline[c], i) - p));
          volumeChanged += bitsAt(volumeFix[c], i) != bitsAt(volumeOriginal[c], i);
        }
        length = std::sqrt(length);
        const double bound = kViewRayBound * length + correctionBound;
        worstFix = std::max(worstFix, fixError / bound);
        worstK = std::max(worstK, correctionBound / length);
        worstBaseline = std::max(worstBaseline, baselineError / length);
        outside += fixError > bound;
        baselineWrong += baselineError > 1000 * bound;
      }
    std::cout << std::setprecision(3) << "[dump far-plane ray] eye " << eye << ": view-space position over " << pixels
              << " pixels, fix error / bound " << worstFix << " (the bound's 1/P00 part at most " << worstK
              << " of |p|); mono baseline max |p - p_exact| / |p| " << worstBaseline << ", beyond 1000x the bound at "
              << baselineWrong << " pixels; a light volume's ray changed at " << volumeChanged << " values\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2);
    EXPECT_EQ(outside, 0u) << "eye " << eye;
    EXPECT_GT(baselineWrong, pixels * 9 / 10) << "eye " << eye << ": the mono baseline should be wrong";
    EXPECT_EQ(volumeChanged, 0u) << "eye " << eye << ": a ray whose z is not the far plane's must be left as it is";
  }
  fullScreenVert_ = fullScreen;
}

// SSAO's or a reflection's step as a decompiled dump writes it: kDumpMadLighting's rebuild, the point
// projected back through the matrix the inverse undoes (cb0[7..10], renderLighting's `forward`, in
// columns) and the depth texture read again where it lands. The pixel's own surface point: in this
// eye's image it is the pixel itself, so the dump writes the NDC x it lands at minus the pixel's.
std::string reprojectionDump() {
  std::string text = kDumpPrologue + R"(  r4.xy = r2.xy;
  r3.xyzw = cb0[1].xyzw * r2.yyyy;
  r3.xyzw = r2.xxxx * cb0[0].xyzw + r3.xyzw;
  r3.xyzw = r1.xxxx * cb0[2].xyzw + r3.xyzw;
  r3.xyzw = cb0[3].xyzw + r3.xyzw;
  r2.xyz = r3.xyz / r3.www;
  r3.xyzw = cb0[8].xyzw * r2.yyyy;
  r3.xyzw = r2.xxxx * cb0[7].xyzw + r3.xyzw;
  r3.xyzw = r2.zzzz * cb0[9].xyzw + r3.xyzw;
  r3.xyzw = cb0[10].xyzw + r3.xyzw;
  r3.xy = r3.xy / r3.ww;
  r5.xy = r3.xy * float2(0.5,0.5) + float2(0.5,0.5);
  r5.xy = r5.xy * cb0[4].xy;
  r5.xy = (int2)r5.xy;
  r5.zw = float2(0,0);
  r5.z = t2.Load(r5.xyz).x;
  r5.w = cmp(2 < r5.z);
  if (r5.w != 0) discard;
  uiDest.x = asuint(r3.x - r4.x);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
}
)";
  const std::string registers = "float4 r0,r1,r2,r3;", rows = "float4 cb0[7];";
  if (text.find(registers) == std::string::npos || text.find(rows) == std::string::npos) return "";
  text.replace(text.find(registers), registers.size(), "float4 r0,r1,r2,r3,r4,r5;");
  return text.replace(text.find(rows), rows.size(), "float4 cb0[11];");
}

// The re-projection's fix by execution: truth (the original with this eye's inverse and this eye's
// view-projection) lands on the pixel; so must the converted dump with the mono matrices and
// StereoParams (the rebuild corrected to the true point, then clip.x + a*s.x*(clip.w - s.y)); the
// converted dump with the re-projection's block taken out (the rebuild alone corrected) lands where
// the mono image has the point, off by s.x*(1 - s.y/w) in NDC: worse than no fix for a screen-space
// effect, whose samples of this eye's image then miss by that much.
void DeferredRender::checkDumpReprojection(const char* name, const std::string& text, bool viewSpace, const char* tag) {
  constexpr double kBound = 4e-6;  // a few ulps of NDC values near 1, through two matrix products
  ASSERT_FALSE(text.empty());
  TranspileResult converted = transpile(SourceFile{name, text}, dumpConversion(TranspileOptions{}));
  ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
  ASSERT_EQ(converted.report["passes"]["deferred-unprojection"]["fixed"].size(), 2u) << converted.report.dump(2);
  const size_t header = converted.output.find("// ---- stereoshift: this eye's re-projection");
  ASSERT_NE(header, std::string::npos) << converted.output;
  const size_t from = converted.output.rfind('\n', header) + 1;
  const std::string end = "// ---- end stereoshift ----\n";
  const size_t to = converted.output.find(end, from);
  ASSERT_NE(to, std::string::npos);
  std::string rebuildOnly = converted.output;
  rebuildOnly.erase(from, to + end.size() - from);
  const auto original = compileOriginal(name, text.c_str(), TranspileOptions{});
  const auto fixedDump = compileOriginal(name, converted.output.c_str(), TranspileOptions{});
  const auto rebuildOnlyDump = compileOriginal(name, rebuildOnly.c_str(), TranspileOptions{});
  const Mat4 viewMatrix = viewSpace ? Mat4{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1} : view();
  const Mat4 monoInverse = inverse(multiply(projection(0), viewMatrix));
  for (double eye : {-1.0, 1.0}) {
    GBuffer g = renderGBuffer(eye);
    if (viewSpace) g = linearDepth(g, projection(0));
    DumpFeed mono{false, false}, stereo{false, true};
    RenderResult truth = renderLighting(g, original, inverse(multiply(projection(eye), viewMatrix)), nullptr, eye, mono);
    RenderResult fixed = renderLighting(g, fixedDump, monoInverse, nullptr, eye, stereo);
    RenderResult unfixed = renderLighting(g, rebuildOnlyDump, monoInverse, nullptr, eye, stereo);
    ASSERT_TRUE(truth.ok() && fixed.ok() && unfixed.ok());
    double worstTruth = 0, worstFix = 0;
    size_t pixels = 0, unfixedWrong = 0;
    for (size_t i = 0; i < g.depthValues.size(); ++i) {
      if (g.depthValues[i] >= 1.0f) continue;
      ++pixels;
      worstTruth = std::max(worstTruth, std::abs(double(bitsAt(truth, i))));
      worstFix = std::max(worstFix, std::abs(double(bitsAt(fixed, i))));
      unfixedWrong += std::abs(double(bitsAt(unfixed, i))) > 1000 * kBound;
    }
    std::cout << std::setprecision(3) << "[" << tag << "] eye " << eye << ": max |ndc - pixel| over " << pixels
              << " pixels: truth " << worstTruth << ", fix " << worstFix
              << "; the rebuild alone corrected: beyond 1000x the bound at " << unfixedWrong << " pixels\n";
    EXPECT_GT(pixels, size_t(kSize) * kSize / 2);
    // A view ray spelled per component reads only the inverse projection's diagonal, so the original
    // with this eye's (sheared) inverse is no truth for it; the fix is checked against the pixel alone.
    if (!viewSpace) EXPECT_LT(worstTruth, kBound) << "eye " << eye;
    EXPECT_LT(worstFix, kBound) << "eye " << eye;
    EXPECT_GT(unfixedWrong, pixels * 9 / 10) << "eye " << eye << ": without the re-projection's fix it should be off";
  }
}

TEST_F(DeferredRender, DumpStyleReprojectionOfTheCorrectedPointLandsOnItsPixelInThisEye) {
  checkDumpReprojection("4b5c6d7e8f901234-ps_replace.txt", reprojectionDump(), false, "dump re-projection");
}

// The same after a per-component view ray (kDumpViewRay's view-space point, its x corrected by the
// ray's fix), projected back through the projection: the re-projection's a is VP's element of x
// times |k|, k = 1/P00 the ray's own element.
TEST_F(DeferredRender, DumpStyleReprojectionOfACorrectedViewRayLandsOnItsPixelInThisEye) {
  std::string text = kDumpPrologue + R"(  r4.x = r2.x;
  r2.xy = r2.xy * r1.xx;
  r3.x = r2.x * cb0[0].x;
  r3.y = r2.y * cb0[1].y;
  r3.z = -r1.x;
  r5.xyzw = cb0[8].xyzw * r3.yyyy;
  r5.xyzw = r3.xxxx * cb0[7].xyzw + r5.xyzw;
  r5.xyzw = r3.zzzz * cb0[9].xyzw + r5.xyzw;
  r5.xyzw = cb0[10].xyzw + r5.xyzw;
  r5.xy = r5.xy / r5.ww;
  r0.xy = r5.xy * float2(0.5,0.5) + float2(0.5,0.5);
  r0.xy = r0.xy * cb0[4].xy;
  r0.xy = (int2)r0.xy;
  r0.zw = float2(0,0);
  r0.z = t2.Load(r0.xyz).x;
  r0.w = cmp(1e30 < r0.z);
  if (r0.w != 0) discard;
  uiDest.x = asuint(r5.x - r4.x);
  o0.xyzw = float4(uiDest.x & 0xffu, (uiDest.x >> 8) & 0xffu, (uiDest.x >> 16) & 0xffu, uiDest.x >> 24) / 255.0;
  return;
}
)";
  text.replace(text.find("float4 r0,r1,r2,r3;"), std::string("float4 r0,r1,r2,r3;").size(), "float4 r0,r1,r2,r3,r4,r5;");
  text.replace(text.find("float4 cb0[7];"), std::string("float4 cb0[7];").size(), "float4 cb0[11];");
  checkDumpReprojection("4b5c6d7e8f901235-ps_replace.txt", text, true, "dump view ray re-projection");
}

}  // namespace
