// Depth reprojection, run time against error, side by side in one run (docs/accuracy-and-benchmarks.md "Depth reprojection"):
// for N in {2, 4, 8, 16, 32} samples x refinement (none, 3 bisection, 3 secant steps) x colour rule
// (nearest, interpolated), the pass's time on lavapipe relative to drawing the scene once, and its
// error against the truth of the execution test's scene (test/harness/reproject_scene.h), left eye
// -> right eye. Times are the fastest of --reps GPU timestamp spans around the render pass (the
// draws alone: a render call also creates its pipelines and uploads the two RGBA32F source textures,
// which took 90-240 ms a call and hid the differences) at 4x the test's size each way (1024x512);
// errors at the test's size. Printed, never asserted; the seed article's configuration (16 linear
// samples, interpolated colour) is marked as the baseline.
//
//   build/bench/reproject_bench [--reps N]
#include "test/harness/reproject_scene.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace stereoshift;
using namespace stereoshift::reproject_scene;

namespace {

// The fastest GPU time of the render pass over `reps` calls of `run` (a RenderResult each), or the
// fastest wall time of the calls where the device writes no timestamps (`timed` says which).
template <class F>
double fastestMs(int reps, F&& run, bool* timed) {
  std::vector<double> ms;
  *timed = true;
  for (int i = 0; i < reps; ++i) {
    auto start = std::chrono::steady_clock::now();
    RenderResult r = run();
    double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (r.drawMilliseconds < 0) *timed = false;
    ms.push_back(r.drawMilliseconds >= 0 ? r.drawMilliseconds : wall);
  }
  return *std::min_element(ms.begin(), ms.end());  // the least disturbed run on a shared machine
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--reps") == 0) reps = std::max(1, std::atoi(argv[i + 1]));
  std::string error;
  auto context = VulkanContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "reproject_bench: no Vulkan device: %s\n", error.c_str());
    return 1;
  }
  Scene scene = makeScene();
  if (!scene.error.empty()) {
    std::fprintf(stderr, "reproject_bench: %s\n", scene.error.c_str());
    return 1;
  }
  DepthSetup depth;
  RenderResult left = renderEye(*context, scene, -1, depth), right = renderEye(*context, scene, 1, depth);
  constexpr uint32_t kTimingScale = 4;
  RenderResult largeLeft = renderEye(*context, scene, -1, depth, kTimingScale);
  if (!left.ok() || !right.ok() || !largeLeft.ok()) {
    std::fprintf(stderr, "reproject_bench: the scene does not render: %s\n", left.error.c_str());
    return 1;
  }
  bool gpuTimes = true, timed = true;
  const double sceneMs = fastestMs(reps, [&] { return renderEye(*context, scene, 1, depth, kTimingScale); }, &timed);
  gpuTimes = gpuTimes && timed;
  std::printf("%s, times at %ux%u, errors at %ux%u; scene drawn once: %.2f ms (fastest of %d)\n",
              context->deviceName().c_str(), kWidth * kTimingScale, kHeight * kTimingScale, kWidth, kHeight, sceneMs, reps);
  std::printf("%-4s %-12s %-13s %9s %9s %9s %10s %8s\n", "N", "refinement", "colour", "pass ms", "x scene", "PSNR dB",
              "wrong %", "holes %");
  struct Refine {
    ReprojectRefinement kind;
    int steps;
    const char* name;
  };
  const Refine refinements[] = {{ReprojectRefinement::None, 0, "none"},
                                {ReprojectRefinement::Bisection, 3, "bisection 3"},
                                {ReprojectRefinement::Secant, 3, "secant 3"}};
  bool failed = false;
  for (int samples : {2, 4, 8, 16, 32})
    for (const Refine& refine : refinements)
      for (ReprojectColour colour : {ReprojectColour::Nearest, ReprojectColour::Interpolated}) {
        ReprojectOptions options = passOptions(depth, ReprojectSource::LeftEye);
        options.samples = samples;
        options.refinement = refine.kind;
        options.refinementSteps = refine.steps;
        options.colour = colour;
        Pass pass = makePass(options);
        if (!pass.error.empty()) {
          std::fprintf(stderr, "%s\n", pass.error.c_str());
          return 1;
        }
        RenderResult out = reproject(*context, pass, left, 1);
        if (!out.ok()) {
          failed = true;
          continue;
        }
        const double passMs = fastestMs(reps, [&] { return reproject(*context, pass, largeLeft, 1); }, &timed);
        gpuTimes = gpuTimes && timed;
        Comparison c = compare(right, left, out, 1, -1, false);
        const bool baseline = samples == 16 && refine.kind == ReprojectRefinement::None && colour == ReprojectColour::Interpolated;
        std::printf("%-4d %-12s %-13s %9.2f %9.2f %9.2f %10.2f %8.2f%s\n", samples, refine.name,
                    reprojectColourName(colour), passMs, passMs / sceneMs, c.psnr, 100.0 * c.wrong / c.pixels,
                    100.0 * c.disoccluded / c.pixels, baseline ? "  <- seed article's configuration" : "");
      }
  std::printf(gpuTimes ? "times: GPU timestamps around the render pass (the draws alone)\n"
                       : "times: whole render calls (this device writes no timestamps): pipeline creation and uploads included\n");
  const Comparison mono = compare(right, left, left, 1, -1, false);
  std::printf("no reprojection (the left image shown to the right eye): PSNR %.2f dB\n", mono.monoPsnr);
  return failed ? 1 : 0;
}
