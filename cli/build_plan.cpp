// The plan of `stereoshift build`: the tree walk (or the manifest's passes over it) made into jobs.
#include "cli/build_plan.h"

#include "cli/build_cache.h"

#include "cli/scene_manifest.h"
#include "core/diagnostics.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/language_detect.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// Canonical paths of many files, each directory resolved once, then a file's own name unless the
// file itself is a symbolic link: weakly_canonical per file reads every link of every component
// again, half of a no-op rebuild's system calls on a large tree. (Native strings as keys:
// std::filesystem::path compares component by component.)
class PathResolver {
 public:
  std::string resolve(const fs::path& file) {
    std::error_code ec;
    if (fs::is_symlink(file, ec)) return fs::weakly_canonical(file, ec).native();
    const fs::path parent = file.parent_path();
    auto [at, fresh] = directories_.try_emplace(parent.native());
    if (fresh) at->second = fs::weakly_canonical(parent.empty() ? fs::path(".") : parent, ec);
    return (at->second / file.filename()).native();
  }

 private:
  std::map<std::string, fs::path> directories_;
};

// `dir/name.vert` -> `dir/name.<variant>.vert` (variant before every extension).
fs::path variantPath(const fs::path& path, const std::string& variant) {
  std::string name = path.filename().string();
  size_t dot = name.find('.');
  std::string renamed = dot == std::string::npos ? name + "." + variant
                                                 : name.substr(0, dot) + "." + variant + name.substr(dot);
  return path.parent_path() / renamed;
}

// The conversion-option keys a manifest may set: the CLI long names, less the per-file and
// debugging ones.
std::vector<std::string> manifestOptionKeys() {
  CliOptions scratch;
  CLI::App app;
  addConversionOptions(app, scratch);
  // stage-ext: the manifest's [stages] table instead, one for the whole tree.
  static const std::set<std::string> excluded = {"help", "report", "pass", "print-all", "validate-each", "stage", "stage-ext", "D", "I"};
  std::vector<std::string> keys;
  for (const CLI::Option* option : app.get_options())
    for (const auto& name : option->get_lnames())
      if (!excluded.count(name)) keys.push_back(name);
  std::sort(keys.begin(), keys.end());
  return keys;
}

// Applies command-line words (`--block-name X`, `-D A`) on top of `o`; lists (defines, include
// directories) are appended to. Returns an error message or "".
std::string applyOptionWords(CliOptions& o, const std::vector<std::string>& words) {
  if (words.empty()) return "";
  CliOptions updated = o;
  updated.t.defines.clear();
  updated.t.includeDirs.clear();
  CLI::App app;
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  addConversionOptions(app, updated);
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  std::vector<std::string> defines = o.t.defines, includes = o.t.includeDirs;
  defines.insert(defines.end(), updated.t.defines.begin(), updated.t.defines.end());
  includes.insert(includes.end(), updated.t.includeDirs.begin(), updated.t.includeDirs.end());
  updated.t.defines = defines;
  updated.t.includeDirs = includes;
  if (auto error = finishOptions(updated)) return *error;
  o = std::move(updated);
  return "";
}

// Walks the tree one directory at a time (recursive_directory_iterator stops at the first entry
// it cannot read, and its entries' queries throw on a symbolic-link loop): an entry that cannot be
// examined is reported and skipped, and the rest of the tree is walked. Symbolic links to
// directories are listed (a build system watches them) but not entered, as before.
class TreeWalk {
 public:
  TreeWalk(const fs::path& outDir, const std::map<std::string, Stage>& stageExtensions, Plan& plan)
      : plan_(plan), stageExtensions_(stageExtensions) {
    std::error_code ec;
    outCanonical_ = fs::weakly_canonical(outDir, ec);
  }

  // Appends the shader files under `dir` to `files`, the directories to the plan's dependencies.
  void walk(const fs::path& dir, std::vector<fs::path>& files) {
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
      const fs::path& path = it->path();
      // Cached from the directory listing unless the entry is a link, which is followed here.
      std::error_code entryError;
      const bool isDirectory = it->is_directory(entryError);
      const bool isFile = !entryError && !isDirectory && it->is_regular_file(entryError);
      if (entryError) {
        // A dangling link has nothing behind it to convert (skipped silently, as before).
        if (entryError != std::errc::no_such_file_or_directory) skipped(path, entryError, "cannot examine this entry");
        continue;
      }
      if (isDirectory) {
        // An output directory inside the source tree is not part of the source: this build's, or
        // an earlier build's (`build tree -o tree/out`, then `-o elsewhere`), known by the cache
        // file or the report a build leaves there.
        if (fs::weakly_canonical(path, entryError) == outCanonical_) continue;
        if (const char* mark = earlierOutputMark(path)) {
          plan_.warnings.push_back(path.string() + ": warning: an earlier stereoshift build's output (it holds " +
                                   mark + "); not read as sources");
          continue;
        }
        plan_.extraDependencies.push_back(path);
        if (!it->is_symlink(entryError)) walk(path, files);
      } else if (isFile && mayBeShader(path)) {
        files.push_back(path);
      }
    }
    // A directory that vanished while the tree was walked (a process's, under /proc) held nothing.
    if (ec && ec != std::errc::no_such_file_or_directory)
      skipped(dir, ec, "cannot read this directory", /*mayHoldShaders=*/true);
  }

 private:
  // An entry with a shader's name (or a directory, which may hold shaders) is an error: the run
  // goes on but says something was not converted. Anything else is a warning.
  void skipped(const fs::path& path, const std::error_code& why, const std::string& what, bool mayHoldShaders = false) {
    const bool error = mayHoldShaders || stageFromPath(path.string(), stageExtensions_).has_value();
    (error ? plan_.skippedEntries : plan_.warnings)
        .push_back(path.string() + (error ? ": error: " : ": warning: ") + what + " (" + why.message() +
                   "); skipped" + (error ? ", the other shaders are converted regardless" : ""));
  }

  // A file the name says is a stage, or a shader-language file (.glsl .hlsl .fx) whose stage its
  // text may say (#pragma shader_stage); which of those are pipelines is decided on their text.
  bool mayBeShader(const fs::path& path) const {
    if (stageFromPath(path.string(), stageExtensions_)) return true;
    if (isIncludeOnlyName(path.string())) return false;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".glsl" || extension == ".hlsl" || extension == ".fx";
  }

  // The file a build leaves in its output directory, when `dir` holds one.
  static const char* earlierOutputMark(const fs::path& dir) {
    std::error_code ec;
    for (const char* mark : {kCacheFile, "stereoshift-report.json"})
      if (fs::exists(dir / mark, ec)) return mark;
    return nullptr;
  }

  Plan& plan_;
  const std::map<std::string, Stage>& stageExtensions_;
  fs::path outCanonical_;
};

}  // namespace

std::vector<fs::path> includedFiles(const fs::path& path, const std::string& text, const std::vector<std::string>& userDirs) {
  std::vector<fs::path> found;
  std::vector<std::string> roots;  // looked up at the first #include: most files have none
  bool rootsKnown = false;
  // Every `#include "file"` / `#include <file>` the lexer reads (under any #if: a dependency of one
  // configuration is one of the build), none in a comment.
  source::Lexer lexer(text);
  source::Token t;
  while (lexer.next(t)) {
    if (t.kind != source::TokenKind::Directive || t.directive != source::DirectiveKind::Include) continue;
    std::vector<source::Token> words = lexer.directiveWords();  // `include` and its operand
    if (words.size() < 2 || words[1].kind != source::TokenKind::String || words[1].unterminated) continue;
    std::string quoted = source::spelledString(text, words[1]);
    if (quoted[0] != '"' && quoted[0] != '<') continue;
    std::string header = quoted.substr(1, quoted.size() - 2);
    if (!rootsKnown) roots = includeSearchPath(path.string(), userDirs);
    rootsKnown = true;
    std::error_code ec;
    for (const auto& root : roots)
      if (fs::is_regular_file(fs::path(root) / header, ec)) {
        found.push_back(fs::weakly_canonical(fs::path(root) / header, ec));
        break;
      }
  }
  return found;
}

namespace {

// Extensions other languages use too (C# .cs, F# .fs): such a file is a shader only when its text
// says so (a #version line, or HLSL constructs), so a tree with tool sources beside the shaders builds.
bool sharedExtensionWithoutShaderText(const fs::path& path, const std::string& text) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".cs" && extension != ".fs") return false;
  if (findVersion(text).begin != std::string::npos) return false;
  return decideLanguage(path.string(), text, std::nullopt).language != SourceLanguage::Hlsl;
}

// Shader files under `root`, grouped into pipelines keyed by their path relative to `root`; the
// directories walked are added to the plan's dependencies, entries that cannot be read to its
// skipped entries or warnings.
//
// The files of a --files-from list as the walk would name them (root / relative path), each
// checked: inside the source directory and a regular file; the others are errors of the plan.
std::vector<fs::path> listedFiles(const fs::path& root, const std::vector<fs::path>& listed, Plan& plan) {
  std::vector<fs::path> files;
  std::error_code ec;
  const fs::path absoluteRoot = fs::absolute(root, ec).lexically_normal();
  for (const fs::path& entry : listed) {
    fs::path relative = entry.is_absolute() ? entry.lexically_normal().lexically_relative(absoluteRoot)
                                            : entry.lexically_normal();
    if (relative.empty() || *relative.begin() == ".." || relative.is_absolute()) {
      plan.errors.push_back(entry.string() + ": error: listed in --files-from but not inside the source directory " +
                            root.string() + " (outputs mirror the paths under it)");
      continue;
    }
    fs::path file = root / relative;
    if (!fs::is_regular_file(file, ec)) {
      plan.errors.push_back(file.string() + ": error: listed in --files-from but " +
                            (fs::exists(file, ec) ? "not a file" : "does not exist"));
      continue;
    }
    files.push_back(std::move(file));
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

// A file is a pipeline stage when its stage can be told (-S, `#pragma shader_stage`, the name) and
// no other file of the tree #includes it; a shader-language file with no stage (common.glsl) is an
// include file. Stages group by the name without the stage part (pipelineKey): 5.1.parallax.vs and
// 5.1.parallax.fs, basicVS.hlsl and basicPS.hlsl, water.vert.glsl and water.frag.glsl.
std::map<std::string, std::vector<fs::path>> findPipelines(const fs::path& root, const fs::path& outDir,
                                                           const CliOptions& base, Plan& plan,
                                                           const std::vector<fs::path>* only = nullptr) {
  std::vector<fs::path> files;
  const std::map<std::string, Stage>& extensions = base.t.stageExtensions;
  if (only) {
    files = listedFiles(root, *only, plan);
  } else {
    plan.extraDependencies.push_back(root);
    TreeWalk(outDir, extensions, plan).walk(root, files);
  }
  std::sort(files.begin(), files.end());
  struct Candidate {
    fs::path path;
    StageDecision stage;
    bool notShaderText = false;
  };
  std::vector<Candidate> candidates;
  std::set<std::string> included;  // canonical, native
  for (const auto& f : files) {
    std::string text;
    // An unreadable stage is reported when its pipeline converts.
    if (readFile(f.string(), &text)) plan.fileDigests.emplace(f.string(), hashBytes(text));
    Candidate c{f, decideStage(f.string(), text, base.t.stage, extensions), sharedExtensionWithoutShaderText(f, text)};
    for (auto& header : includedFiles(f, text, base.t.includeDirs)) included.insert(header.native());
    candidates.push_back(std::move(c));
  }
  std::map<std::string, std::vector<fs::path>> pipelines;
  PathResolver resolver;
  for (const auto& c : candidates) {
    if (!included.empty() && included.count(resolver.resolve(c.path))) continue;  // an include file of another shader
    if (!c.stage.problem.empty()) {
      plan.skippedEntries.push_back(c.path.string() + ":" + std::to_string(c.stage.problemLine) + ":" +
                                    std::to_string(c.stage.problemColumn) + ": error: " + c.stage.problem +
                                    "; skipped, the other shaders are converted regardless");
      continue;
    }
    if (c.notShaderText) {
      plan.warnings.push_back(c.path.string() + ": warning: named like a shader stage, but has no #version line "
                              "and no HLSL constructs (C#/F# source?); skipped");
      continue;
    }
    if (!c.stage.stage) {
      plan.warnings.push_back(c.path.string() + ": warning: not converted: " + stageHint(c.path.string()) +
                              " (a file another shader #includes needs none)");
      continue;
    }
    // Lexical: every file came from walking `root` (fs::relative would resolve both paths per file).
    pipelines[pipelineKey(c.path.lexically_relative(root).generic_string(), extensions)].push_back(c.path);
  }
  return pipelines;
}

// The options a pass converts with, and their description for the cache key (computed once per
// pass: describing the options per pipeline cost a fifth of a no-op rebuild of a large tree).
struct RenderPassOptions {
  TranspileOptions options;
  std::string fingerprint;  // the options (before per-pipeline include roots) and the mode
};

RenderPassOptions passOptions(const CliOptions& options, PassMode mode) {
  RenderPassOptions p{options.t, ""};
  if (mode == PassMode::Deferred) p.options.deferredUnprojection = true;
  if (mode == PassMode::UiAtDepth) p.options.hudAtDepth = true;
  nlohmann::json fingerprint = describeOptions(p.options);
  fingerprint["mode"] = toString(mode);
  p.fingerprint = fingerprint.dump();
  return p;
}

void addJob(Plan& plan, const fs::path& outDir, const std::string& key, const std::vector<fs::path>& stages,
            const RenderPassOptions& options, const std::string& pass, PassMode mode, bool variant) {
  BuildJob job;
  job.id = variant ? key + "@" + pass : key;
  job.stages = stages;
  job.pass = pass;
  job.mode = mode;
  job.options = options.options;
  job.fingerprint = options.fingerprint;
  // Each shader's directory and an `include` directory beside it are include roots (the front end
  // adds the same for a single shader; here they also enter the cache key).
  for (const auto& s : stages) job.options.includeDirs = includeSearchPath(s.string(), job.options.includeDirs);
  for (size_t i = options.options.includeDirs.size(); i < job.options.includeDirs.size(); ++i)
    job.fingerprint += "\n-I" + job.options.includeDirs[i];
  for (const auto& s : stages) {
    fs::path out = outDir / s.lexically_relative(plan.root);
    if (variant) out = variantPath(out, pass);
    job.outputs.push_back(out);
  }
  plan.jobs.push_back(std::move(job));
}

}  // namespace

Plan planDirectory(const fs::path& root, const fs::path& outDir, const CliOptions& base,
                   const std::vector<fs::path>* only) {
  Plan plan;
  plan.root = root;
  plan.outputDir = outDir;
  RenderPassOptions options = passOptions(base, PassMode::Stereo);
  for (const auto& [key, stages] : findPipelines(root, outDir, base, plan, only))
    addJob(plan, outDir, key, stages, options, "", PassMode::Stereo, false);
  return plan;
}

Plan planManifest(const fs::path& manifestFile, const fs::path& outDir, const CliOptions& base) {
  Plan plan;
  plan.outputDir = outDir;
  plan.extraDependencies.push_back(manifestFile);
  SceneManifest manifest;
  auto check = [](const std::vector<std::string>& words) {
    CliOptions scratch;
    return applyOptionWords(scratch, words);
  };
  if (!loadSceneManifest(manifestFile, manifestOptionKeys(), check, &manifest, &plan.errors)) return plan;
  plan.root = manifest.sourceRoot;
  std::error_code ec;
  if (!fs::is_directory(plan.root, ec)) {
    plan.errors.push_back(manifestFile.string() + ":1:1: error: source directory '" + plan.root.string() +
                          "' does not exist");
    return plan;
  }
  // The manifest's [stages] table, under the command line's --stage-ext (which wins for an extension
  // both name): the walk and every pass's conversion read the same extensions.
  CliOptions withStages = base;
  for (const auto& [extension, stage] : manifest.stageExtensions) withStages.t.stageExtensions.try_emplace(extension, stage);
  auto pipelines = findPipelines(plan.root, outDir, withStages, plan);

  CliOptions defaults = withStages;
  for (const auto& o : manifest.defaults) applyOptionWords(defaults, o.words);  // checked while loading

  // Which passes use each pipeline, in manifest order.
  std::map<std::string, std::vector<const ScenePass*>> users;
  for (const auto& pass : manifest.passes)
    for (const auto& [pattern, where] : pass.pipelines) {
      int matched = 0;
      for (const auto& [key, stages] : pipelines)
        if (pipelineMatches(pattern, key)) {
          auto& list = users[key];
          if (std::find(list.begin(), list.end(), &pass) == list.end()) list.push_back(&pass);
          ++matched;
        }
      if (!matched)
        plan.errors.push_back(manifestFile.string() + ":" + std::to_string(where.line) + ":" +
                              std::to_string(where.column) + ": error: pass '" + pass.name + "': '" + escapeControlBytes(pattern) +
                              "' matches no pipeline under " + plan.root.string());
    }
  std::map<const ScenePass*, RenderPassOptions> optionsOf;
  for (const auto& pass : manifest.passes) {
    CliOptions options = defaults;
    for (const auto& o : pass.options) applyOptionWords(options, o.words);
    optionsOf.emplace(&pass, passOptions(options, pass.mode));
  }
  std::vector<std::string> unused;
  for (const auto& [key, stages] : pipelines) {
    auto it = users.find(key);
    if (it == users.end()) {
      unused.push_back(key);
      continue;
    }
    bool variants = it->second.size() > 1;
    for (const ScenePass* pass : it->second) addJob(plan, outDir, key, stages, optionsOf.at(pass), pass->name, pass->mode, variants);
  }
  if (!unused.empty()) {
    std::string list;
    for (size_t i = 0; i < unused.size() && i < 5; ++i) list += (i ? ", " : "") + unused[i];
    if (unused.size() > 5) list += ", ...";
    plan.warnings.push_back(manifestFile.string() + ": warning: " + std::to_string(unused.size()) +
                            " pipeline(s) used by no pass are not emitted: " + list);
  }
  return plan;
}

bool insideDirectory(const fs::path& path, const fs::path& directory) {
  fs::path p = path.lexically_normal(), d = directory.lexically_normal();
  auto [end, _] = std::mismatch(d.begin(), d.end(), p.begin(), p.end());
  return end == d.end() || (std::next(end) == d.end() && end->empty());
}

std::string checkOutputPlacement(const Plan& plan, const fs::path& outDir) {
  // A link into the tree would put outputs among the sources, and the walk skips its target as the
  // output directory. (A real output folder nested in the tree is fine: the walk skips it.)
  fs::path bare = outDir.lexically_normal();
  if (!bare.has_filename()) bare = bare.parent_path();  // `out/`: the link, not what it points at
  std::error_code linkError;
  if (fs::is_symlink(bare, linkError)) {
    fs::path target = fs::weakly_canonical(bare, linkError), root = fs::weakly_canonical(plan.root, linkError);
    if (insideDirectory(target, root))
      return outDir.string() + ": error: the output directory is a symbolic link into the source tree (to '" +
             target.string() + "'); outputs would be written among the sources";
  }
  // The output directory is the source tree or holds it (`build src/gl330 -o src`): the outputs and
  // the cache would land beside other sources, so it is refused as `-o` naming an input is.
  {
    std::error_code resolveError;
    fs::path out = fs::weakly_canonical(outDir, resolveError), root = fs::weakly_canonical(plan.root, resolveError);
    if (!resolveError && insideDirectory(root, out))
      return outDir.string() + ": error: the output directory " + (out == root ? "is" : "holds") +
             " the source tree '" + plan.root.string() + "'; outputs would be written among the sources (choose a "
             "directory outside the tree, or one inside it)";
  }
  PathResolver resolver;
  std::set<std::string> inputs;
  for (const auto& job : plan.jobs)
    for (const auto& s : job.stages) inputs.insert(resolver.resolve(s));
  for (const auto& job : plan.jobs)
    for (const auto& out : job.outputs)
      if (!insideDirectory(out, outDir) || inputs.count(resolver.resolve(out)))
        return out.string() + ": error: output would be outside the output directory or overwrite an input";
  return "";
}

std::string linkOutOfOutputDirectory(const fs::path& output, const fs::path& outDir) {
  std::error_code ec;
  const fs::path outCanonical = fs::weakly_canonical(outDir, ec);
  fs::path walked = outDir;
  for (const auto& component : output.lexically_relative(outDir)) {
    walked /= component;
    fs::file_status status = fs::symlink_status(walked, ec);
    if (!fs::exists(status)) break;  // nothing further exists yet: written as plain files
    if (!fs::is_symlink(status)) continue;
    fs::path target = fs::weakly_canonical(walked, ec);
    if (!insideDirectory(target, outCanonical))
      return "'" + walked.string() + "' is a symbolic link out of the output directory (to '" + target.string() +
             "'); not written through it";
  }
  return "";
}

}  // namespace stereoshift
