#include "cli/scene_manifest.h"
#include "core/diagnostics.h"
#include "transpiler/source/stage_rules.h"

#include <toml++/toml.h>

#include <fnmatch.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {

const char* toString(PassMode mode) {
  switch (mode) {
    case PassMode::Mono: return "mono";
    case PassMode::Stereo: return "stereo";
    case PassMode::Deferred: return "deferred";
    case PassMode::Post: return "post";
    case PassMode::Ui: return "ui";
    case PassMode::UiAtDepth: return "ui-at-depth";
  }
  return "?";
}

bool convertsShaders(PassMode mode) {
  return mode == PassMode::Stereo || mode == PassMode::Deferred || mode == PassMode::UiAtDepth;
}

bool pipelineMatches(const std::string& pattern, const std::string& key) {
  return ::fnmatch(pattern.c_str(), key.c_str(), FNM_PATHNAME) == 0;
}

namespace {

ManifestLocation locationOf(const toml::source_region& source) {
  return {static_cast<int>(source.begin.line), static_cast<int>(source.begin.column)};
}
ManifestLocation locationOf(const toml::node& node) { return locationOf(node.source()); }
ManifestLocation locationOf(const toml::key& key) { return locationOf(key.source()); }

// The closest of `candidates` to `word` (edit distance <= 2), for "did you mean".
std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t bestDistance = 3;
  for (const auto& c : candidates) {
    std::vector<size_t> row(c.size() + 1);
    for (size_t j = 0; j <= c.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= word.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= c.size(); ++j) {
        size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (word[i - 1] == c[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    if (row[c.size()] < bestDistance) {
      bestDistance = row[c.size()];
      best = c;
    }
  }
  return best;
}

class Loader {
 public:
  Loader(const fs::path& file, const std::vector<std::string>& optionKeys,
         const std::function<std::string(const std::vector<std::string>&)>& checkOption, std::vector<std::string>* errors)
      : file_(file), optionKeys_(optionKeys), checkOption_(checkOption), errors_(errors) {}

  // Messages quote manifest text (names, keys, modes, toml++'s own excerpts); a TOML multi-line string can
  // put a line break in it, and one diagnostic stays one line.
  void error(ManifestLocation at, const std::string& message) {
    errors_->push_back(file_.string() + ":" + std::to_string(std::max(1, at.line)) + ":" +
                       std::to_string(std::max(1, at.column)) + ": error: " + escapeControlBytes(message));
  }

  void unknownKey(const toml::key& key, const std::vector<std::string>& accepted, const std::string& where) {
    std::string hint = closest(std::string(key.str()), accepted);
    error(locationOf(key), "unknown key '" + std::string(key.str()) + "'" + where +
                                (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }

  // A conversion option: a string / number becomes `--key value`, `true` becomes the flag `--key`,
  // an array (defines, include-dirs) one word pair per element.
  bool option(const toml::key& key, const toml::node& value, std::vector<ManifestOption>* out) {
    std::string name(key.str());
    ManifestOption o{name, {}, locationOf(key)};
    auto scalarWord = [&](const toml::node& v, std::string* word) {
      if (auto s = v.value<std::string>()) *word = *s;
      else if (v.is_integer()) *word = std::to_string(*v.value<int64_t>());
      else if (v.is_floating_point()) {
        std::ostringstream text;
        text.precision(9);
        text << *v.value<double>();
        *word = text.str();
      } else return false;
      return true;
    };
    if (name == "defines" || name == "include-dirs") {
      const toml::array* list = value.as_array();
      if (!list) {
        error(locationOf(value), "'" + name + "' must be an array of strings");
        return false;
      }
      for (const auto& element : *list) {
        auto s = element.value<std::string>();
        if (!s) {
          error(locationOf(element), "'" + name + "' must be an array of strings");
          return false;
        }
        std::string word = *s;
        if (name == "include-dirs" && fs::path(word).is_relative()) word = (file_.parent_path() / word).lexically_normal().string();
        o.words.push_back(name == "defines" ? "-D" : "-I");
        o.words.push_back(word);
      }
    } else {
      if (std::find(optionKeys_.begin(), optionKeys_.end(), name) == optionKeys_.end()) {
        std::vector<std::string> accepted = optionKeys_;
        accepted.insert(accepted.end(), {"defines", "include-dirs"});
        unknownKey(key, accepted, " (not a conversion option)");
        return false;
      }
      if (auto flag = value.value<bool>(); value.is_boolean()) {
        if (!*flag) {
          error(locationOf(value), "'" + name + "' is a flag: write `" + name + " = true` or leave it out");
          return false;
        }
        o.words = {"--" + name};
      } else {
        std::string word;
        if (!scalarWord(value, &word)) {
          error(locationOf(value), "'" + name + "' needs a string, a number or true");
          return false;
        }
        o.words = {"--" + name, word};
      }
      std::string problem = checkOption_(o.words);
      if (!problem.empty()) {
        error(locationOf(value), "'" + name + "': " + problem);
        return false;
      }
    }
    out->push_back(std::move(o));
    return true;
  }

  bool options(const toml::table& table, const std::set<std::string>& skip, std::vector<ManifestOption>* out) {
    bool ok = true;
    for (const auto& [key, value] : table)
      if (!skip.count(std::string(key.str()))) ok &= option(key, value, out);
    return ok;
  }

  bool pass(const toml::table& table, ScenePass* pass, std::set<std::string>* names) {
    pass->where = locationOf(table);
    bool ok = true;
    const toml::node* name = table.get("name");
    if (!name || !name->is_string()) {
      error(pass->where, "every [[pass]] needs a `name` (a string)");
      return false;
    }
    pass->name = *name->value<std::string>();
    if (pass->name.empty() || pass->name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos) {
      error(locationOf(*name), "pass name '" + pass->name + "' must be letters, digits, '_' or '-' (it names output variants)");
      ok = false;
    }
    if (!names->insert(pass->name).second) {
      error(locationOf(*name), "a pass named '" + pass->name + "' is already defined");
      ok = false;
    }
    const toml::node* mode = table.get("mode");
    static const std::vector<std::pair<std::string, PassMode>> modes = {
        {"mono", PassMode::Mono}, {"stereo", PassMode::Stereo}, {"deferred", PassMode::Deferred},
        {"post", PassMode::Post}, {"ui", PassMode::Ui}, {"ui-at-depth", PassMode::UiAtDepth}};
    if (!mode || !mode->is_string()) {
      error(mode ? locationOf(*mode) : pass->where,
            "pass '" + pass->name + "' needs a `mode`: mono, stereo, deferred, post, ui or ui-at-depth");
      ok = false;
    } else {
      std::string m = *mode->value<std::string>();
      auto it = std::find_if(modes.begin(), modes.end(), [&](const auto& p) { return p.first == m; });
      if (it == modes.end()) {
        error(locationOf(*mode), "unknown mode '" + m + "' in pass '" + pass->name +
                                     "' (mono, stereo, deferred, post, ui, ui-at-depth)");
        ok = false;
      } else {
        pass->mode = it->second;
      }
    }
    const toml::node* pipelines = table.get("pipelines");
    if (!pipelines || !pipelines->is_array() || pipelines->as_array()->empty()) {
      error(pipelines ? locationOf(*pipelines) : pass->where,
            "pass '" + pass->name + "' needs `pipelines`: a non-empty array of pipeline names or globs");
      ok = false;
    } else {
      for (const auto& p : *pipelines->as_array()) {
        if (!p.is_string()) {
          error(locationOf(p), "`pipelines` entries must be strings");
          ok = false;
          continue;
        }
        pass->pipelines.emplace_back(*p.value<std::string>(), locationOf(p));
      }
    }
    ok &= options(table, {"name", "mode", "pipelines"}, &pass->options);
    return ok;
  }

  // [stages]: `vp = "vert"` reads files ending in .vp as vertex shaders.
  bool stages(const toml::node& value, SceneManifest* manifest) {
    const toml::table* table = value.as_table();
    if (!table) {
      error(locationOf(value), "`stages` must be a table ([stages], `ext = \"stage\"`)");
      return false;
    }
    bool ok = true;
    for (const auto& [key, stage] : *table) {
      std::string extension(key.str());
      while (!extension.empty() && extension.front() == '.') extension.erase(0, 1);
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      auto name = stage.value<std::string>();
      std::optional<Stage> decided = name ? stageFromName(*name) : std::nullopt;
      if (extension.empty() || extension.find_first_of("./") != std::string::npos) {
        error(locationOf(key), "[stages]: '" + std::string(key.str()) + "' is not a file extension");
        ok = false;
      } else if (!decided) {
        error(locationOf(stage), "[stages]: extension '" + extension +
                                     "' needs a stage name (vert, tesc, tese, geom, frag, comp, mesh, task, rgen, rint, rahit, rchit, rmiss, rcall)");
        ok = false;
      } else {
        manifest->stageExtensions[extension] = *decided;
      }
    }
    return ok;
  }

  bool load(SceneManifest* manifest) {
    toml::table root;
    try {
      root = toml::parse_file(file_.string());
    } catch (const toml::parse_error& e) {
      // toml++ quotes the offending text as it is, line breaks included; error() escapes them.
      error(ManifestLocation{static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)},
            std::string(e.description()));
      return false;
    }
    manifest->file = file_;
    manifest->sourceRoot = file_.parent_path();
    bool ok = true;
    for (const auto& [key, value] : root) {
      std::string k(key.str());
      if (k == "source") {
        auto s = value.value<std::string>();
        if (!s) {
          error(locationOf(value), "`source` must be a string (a directory relative to the manifest)");
          ok = false;
        } else {
          manifest->sourceRoot = (file_.parent_path() / *s).lexically_normal();
        }
      } else if (k == "defaults") {
        if (const toml::table* t = value.as_table()) ok &= options(*t, {}, &manifest->defaults);
        else {
          error(locationOf(value), "`defaults` must be a table ([defaults])");
          ok = false;
        }
      } else if (k == "pass") {
        const toml::array* passes = value.as_array();
        if (!passes || !passes->is_array_of_tables()) {
          error(locationOf(value), "`pass` must be an array of tables ([[pass]])");
          ok = false;
          continue;
        }
        std::set<std::string> names;
        for (const auto& p : *passes) {
          ScenePass pass;
          ok &= this->pass(*p.as_table(), &pass, &names);
          manifest->passes.push_back(std::move(pass));
        }
      } else if (k == "stages") {
        ok &= stages(value, manifest);
      } else if (k == "version") {
        if (value.value<int64_t>() != 1) {
          error(locationOf(value), "unsupported manifest version (this stereoshift reads version = 1)");
          ok = false;
        }
      } else {
        unknownKey(key, {"version", "source", "defaults", "stages", "pass"}, " at the top level");
        ok = false;
      }
    }
    if (ok && manifest->passes.empty()) {
      error(ManifestLocation{1, 1}, "the manifest defines no [[pass]]");
      ok = false;
    }
    return ok;
  }

 private:
  fs::path file_;
  const std::vector<std::string>& optionKeys_;
  const std::function<std::string(const std::vector<std::string>&)>& checkOption_;
  std::vector<std::string>* errors_;
};

}  // namespace

bool loadSceneManifest(const fs::path& file, const std::vector<std::string>& optionKeys,
                       const std::function<std::string(const std::vector<std::string>&)>& checkOption,
                       SceneManifest* manifest, std::vector<std::string>* errors) {
  Loader loader(file, optionKeys, checkOption, errors);
  return loader.load(manifest);
}

}  // namespace stereoshift
