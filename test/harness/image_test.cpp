// Image-level ground truth: a test scene (quads at eye depths C/2 .. 100 C, an orthographic HUD quad,
// a full-screen post pass) rendered per eye two ways on lavapipe:
//   truth:      the original shaders with the stereo projection matrix (mono P with row 0 changed to
//               [p00, 0, p02 - e S, -e S C], docs/stereo-math.md section 1), the HUD and post pass untouched;
//   transpiled: stereoshift's shaders with the eye parameters, every matrix mono.
// Differences may only be rasterization ties: every differing pixel must lie on an edge of the
// truth image. Left, right and a red/cyan anaglyph are written as PNG for a person to look at.
#include "transpiler/verify/stereo_verify.h"
#include "transpiler/frontend/front_end.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

const char* kSceneVert = R"(#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 proj; mat4 view; } cam;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inColor;
layout(location = 0) out vec3 vColor;
void main() {
  vColor = inColor;
  gl_Position = cam.proj * cam.view * vec4(inPosition, 1.0);
}
)";

const char* kHudVert = R"(#version 450
layout(set = 0, binding = 0) uniform Hud { mat4 ortho; } hud;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inColor;
layout(location = 0) out vec3 vColor;
void main() {
  vColor = inColor;
  gl_Position = hud.ortho * vec4(inPosition.xy, 0.0, 1.0);
}
)";

const char* kPostVert = R"(#version 450
layout(location = 0) out vec3 vColor;
void main() {
  vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  vColor = vec3(0.0, 0.0, 0.25);
  gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* kFrag = R"(#version 450
layout(location = 0) in vec3 vColor;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(vColor, 0.5); }
)";

constexpr uint32_t kSize = 256;
constexpr float kSeparation = 0.06f, kConvergence = 4.0f;

std::vector<uint32_t> compile(const char* name, const char* text, const TranspileOptions& options, bool transpiled) {
  SourceFile file{name, text};
  if (!transpiled) {
    Diagnostics diags;
    FrontEndResult front = compileToSpirv(file, options, diags);
    EXPECT_TRUE(front.ok) << diags.format();
    return front.spirv;
  }
  TranspileOptions o = options;
  o.target = TargetLanguage::Spirv;
  TranspileResult r = transpile(file, o);
  EXPECT_TRUE(r.ok) << r.diagnostics.format();
  std::vector<uint32_t> words(r.output.size() / 4);
  std::memcpy(words.data(), r.output.data(), words.size() * 4);
  return words;
}

// Column-major, Vulkan clip space (y down, depth 0..1), w = -z_eye.
std::array<float, 16> projection(float eye) {
  const float f = 1.0f / std::tan(0.5f * 1.0f), n = 0.1f, far = 1000.0f;
  std::array<float, 16> p{};
  p[0] = f;
  p[5] = -f;
  p[10] = far / (n - far);
  p[11] = -1.0f;
  p[14] = n * far / (n - far);
  // Stereo projection: row 0 = [p00, 0, p02 - e S, -e S C] (p02 = 0 here).
  p[8] = -eye * kSeparation;
  p[12] = -eye * kSeparation * kConvergence;
  return p;
}

std::vector<uint8_t> floats(std::initializer_list<std::array<float, 16>> matrices) {
  std::vector<uint8_t> bytes;
  for (const auto& m : matrices) {
    size_t at = bytes.size();
    bytes.resize(at + 64);
    std::memcpy(bytes.data() + at, m.data(), 64);
  }
  return bytes;
}

VertexBuffer quads(const std::vector<std::array<float, 7>>& rects) {  // x0, x1, y0, y1, z, colour index, unused
  static const float palette[][3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.4f, 1}, {1, 1, 0.2f}, {1, 0.3f, 1}, {0.9f, 0.9f, 0.9f}};
  VertexBuffer vb;
  vb.stride = 24;
  vb.attributes = {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, VK_FORMAT_R32G32B32_SFLOAT, 12}};
  for (const auto& r : rects) {
    const float* c = palette[static_cast<int>(r[5])];
    float corners[6][2] = {{r[0], r[2]}, {r[1], r[2]}, {r[1], r[3]}, {r[0], r[2]}, {r[1], r[3]}, {r[0], r[3]}};
    for (auto& xy : corners) {
      float v[6] = {xy[0], xy[1], r[4], c[0], c[1], c[2]};
      size_t at = vb.bytes.size();
      vb.bytes.resize(at + 24);
      std::memcpy(vb.bytes.data() + at, v, 24);
    }
  }
  return vb;
}

struct Images {
  RenderResult left, right;
};

TEST(ImageGroundTruth, TranspiledMatchesStereoProjection) {
  std::string error;
  auto context = VulkanContext::create(&error);
  ASSERT_TRUE(context) << error;

  TranspileOptions options;
  auto sceneOriginal = compile("scene.vert", kSceneVert, options, false);
  auto sceneStereo = compile("scene.vert", kSceneVert, options, true);
  auto hudOriginal = compile("hud.vert", kHudVert, options, false);
  auto hudStereo = compile("hud.vert", kHudVert, options, true);
  auto postOriginal = compile("post.vert", kPostVert, options, false);
  auto postStereo = compile("post.vert", kPostVert, options, true);
  auto frag = compile("color.frag", kFrag, options, false);
  ASSERT_EQ(postStereo, postOriginal);  // constant w = 1: nothing injected

  // Quads at eye depths C/2, C, 2C, 10C, 100C; each spans the same angular size.
  std::vector<std::array<float, 7>> rects;
  const float depths[] = {0.5f * kConvergence, kConvergence, 2 * kConvergence, 10 * kConvergence, 100 * kConvergence};
  for (int i = 0; i < 5; ++i) {
    float d = depths[i], x = -0.44f + 0.22f * i;
    rects.push_back({(x - 0.07f) * d, (x + 0.07f) * d, (-0.25f + 0.05f * i) * d, (0.2f + 0.03f * i) * d, -d, float(i), 0});
  }
  VertexBuffer scene = quads(rects);
  VertexBuffer hud = quads({{-0.9f, -0.5f, 0.7f, 0.9f, 0.0f, 5, 0}});
  std::array<float, 16> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  auto render = [&](float eye, bool transpiled) {
    RenderRequest request;
    request.width = request.height = kSize;
    Draw meshes, overlay, post;
    meshes.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, transpiled ? sceneStereo : sceneOriginal, "main"},
                              {VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main"}};
    meshes.pipeline.vertices = scene;
    meshes.pipeline.vertexCount = static_cast<uint32_t>(rects.size() * 6);
    meshes.pipeline.uniformBuffers = {{0, 0, floats({projection(transpiled ? 0.0f : eye), identity})}};
    overlay.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, transpiled ? hudStereo : hudOriginal, "main"},
                               {VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main"}};
    overlay.pipeline.vertices = hud;
    overlay.pipeline.vertexCount = 6;
    overlay.pipeline.uniformBuffers = {{0, 0, floats({identity})}};
    overlay.depthTest = false;
    if (transpiled) {
      float params[4] = {eye, kSeparation, kConvergence, 0};
      std::vector<uint8_t> bytes(16);
      std::memcpy(bytes.data(), params, 16);
      meshes.pipeline.uniformBuffers.push_back({0, 1, bytes});
      overlay.pipeline.uniformBuffers.push_back({0, 1, bytes});
    }
    post.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, transpiled ? postStereo : postOriginal, "main"},
                            {VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main"}};
    post.pipeline.vertexCount = 3;
    post.depthTest = false;
    post.alphaBlend = true;
    request.draws = {meshes, overlay, post};
    RenderResult result = context->render(request);
    EXPECT_TRUE(result.ok()) << result.error;
    return result;
  };

  size_t totalDiffering = 0;
  int maxDifference = 0;
  RenderResult eyes[2];
  for (int e = 0; e < 2; ++e) {
    float eye = e == 0 ? -1.0f : 1.0f;
    RenderResult truth = render(eye, false);
    RenderResult ours = render(eye, true);
    ASSERT_TRUE(truth.ok() && ours.ok());
    size_t differing = 0, offEdge = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        if (std::memcmp(truth.pixel(x, y), ours.pixel(x, y), 4) == 0) continue;
        ++differing;
        for (int c = 0; c < 4; ++c)
          maxDifference = std::max(maxDifference, std::abs(int(truth.pixel(x, y)[c]) - int(ours.pixel(x, y)[c])));
        // A rasterization tie: the truth changes colour next to this pixel.
        bool edge = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int nx = int(x) + dx, ny = int(y) + dy;
            if (nx < 0 || ny < 0 || nx >= int(kSize) || ny >= int(kSize)) continue;
            edge |= std::memcmp(truth.pixel(x, y), truth.pixel(nx, ny), 4) != 0;
          }
        offEdge += !edge;
      }
    std::cout << "[image] eye " << eye << ": " << differing << " differing pixels of " << kSize * kSize
              << ", all on edges: " << (offEdge == 0 ? "yes" : "no") << "\n";
    EXPECT_EQ(offEdge, 0u) << "eye " << eye << ": differences away from any edge are not rasterization ties";
    totalDiffering += differing;
    eyes[e] = std::move(ours);
  }
  std::cout << "[image] max channel difference " << maxDifference << "\n";
  // The two eyes must differ (the shift happened) while the HUD corner stays identical in both.
  EXPECT_NE(eyes[0].pixels, eyes[1].pixels);
  EXPECT_EQ(std::memcmp(eyes[0].pixel(30, 20), eyes[1].pixel(30, 20), 4), 0) << "HUD moved between eyes";

  std::vector<uint8_t> anaglyph = harness::anaglyph(eyes[0].pixels, eyes[1].pixels, kSize * kSize);
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/stereo_left.png", kSize, kSize, eyes[0].pixels.data()));
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/stereo_right.png", kSize, kSize, eyes[1].pixels.data()));
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/stereo_anaglyph.png", kSize, kSize, anaglyph.data()));
  std::cout << "[image] wrote " IMAGE_OUT_DIR "/stereo_{left,right,anaglyph}.png, " << totalDiffering
            << " differing pixels in total\n";
}

}  // namespace
