// The scene manifest (TOML): the render passes of a scene, what each does with stereo, the
// pipelines each one draws with, and per-pass conversion options. See docs/trees-and-manifests.md "Scene manifest".
//
//   source = "shaders"            # shader tree root, relative to the manifest (default: its directory)
//   [defaults]                    # conversion options for every converted pass (CLI long names)
//   eye-source = "uniform-block"
//   [stages]                      # more stage extensions: `ext = "stage"` (like --stage-ext ext=stage)
//   vp = "vert"
//   [[pass]]
//   name = "main"                 # [A-Za-z0-9_-]+; names variants
//   mode = "stereo"               # mono | stereo | deferred | post | ui | ui-at-depth
//   pipelines = ["forward_lit", "terrain/*"]   # pipeline keys (dir/base name) or globs
//   block-name = "StereoParams"   # any conversion option, overriding [defaults]
#pragma once

#include "core/shader.h"

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

enum class PassMode {
  Mono,       // shadow / light-space passes: drawn once, left alone
  Stereo,     // main / forward: the shift and the per-eye fixes
  Deferred,   // deferred lighting: stereo, with the unprojection fix required
  Post,       // full-screen post-processing: drawn per eye, no projection: left alone
  Ui,         // HUD drawn mono: left alone
  UiAtDepth,  // HUD placed at an eye depth (--hud-at-depth)
};
const char* toString(PassMode mode);
bool convertsShaders(PassMode mode);  // false: the pass's shaders are copied through

struct ManifestLocation {
  int line = 0, column = 0;
};

// A conversion option from the manifest: the CLI long name, its values as command-line words, and
// where it was written (for errors).
struct ManifestOption {
  std::string key;
  std::vector<std::string> words;  // e.g. {"--block-name", "Stereo"} or {"-D", "A=1", "-D", "B"}
  ManifestLocation where;
};

struct ScenePass {
  std::string name;
  PassMode mode = PassMode::Stereo;
  std::vector<std::pair<std::string, ManifestLocation>> pipelines;  // patterns as written
  std::vector<ManifestOption> options;
  ManifestLocation where;
};

struct SceneManifest {
  std::filesystem::path file;
  std::filesystem::path sourceRoot;
  std::map<std::string, Stage> stageExtensions;  // [stages]: extension (lower case, no dot) -> stage
  std::vector<ManifestOption> defaults;
  std::vector<ScenePass> passes;
};

// Parses and validates `file`. `optionKeys` are the accepted conversion-option keys (CLI long
// names); `checkOption` validates one option's words and returns an error message or "". On error
// returns false with `file:line:col: error: ...` lines appended to `errors`.
bool loadSceneManifest(const std::filesystem::path& file, const std::vector<std::string>& optionKeys,
                       const std::function<std::string(const std::vector<std::string>&)>& checkOption,
                       SceneManifest* manifest, std::vector<std::string>* errors);

// Whether pipeline key `key` (relative to the source root, '/'-separated) matches `pattern`.
bool pipelineMatches(const std::string& pattern, const std::string& key);

}  // namespace stereoshift
