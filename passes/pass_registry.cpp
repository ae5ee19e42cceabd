// The registry (see pass_registry.h): each pass's entry lives beside its code (xxxPassInfo() in its
// file: what it needs, what its change preserves, what kind of edit it is); the list's order is the
// pipeline's, and each entry's whyHere says what fixes its position.
#include "passes/pass_registry.h"

#include <algorithm>

namespace stereoshift {

const std::vector<PassInfo>& passRegistry() {
  static const std::vector<PassInfo> registry = {
      clipPositionDetectionPassInfo(),
      hudAtDepthPassInfo(),
      singlePassStereoPassInfo(),
      eyeParamsPassInfo(),
      haloPassInfo(),
      stereoShiftPassInfo(),
      perEyeViewPassInfo(),
      deferredUnprojectionPassInfo(),
  };
  return registry;
}

bool passRunsFor(const PassInfo& info, const PassOptions& options) {
  return !info.runsFor || info.runsFor(options);
}

const PassInfo* findPass(std::string_view name) {
  for (const auto& info : passRegistry())
    if (name == info.name) return &info;
  return nullptr;
}

std::string passNameList() {
  std::string list;
  for (const auto& info : passRegistry()) list += (list.empty() ? "" : ", ") + std::string(info.name);
  return list;
}

std::string passHelpText() {
  std::string text = "Run only this pass and the passes it requires (repeatable), in pipeline order: " + passNameList();
  for (const auto& info : passRegistry()) {
    text += "\n  " + std::string(info.name) + ": " + info.description + " [" + info.enabledBy + "]";
    if (!info.requiredPasses.empty()) {
      text += " (requires ";
      for (size_t i = 0; i < info.requiredPasses.size(); ++i) text += (i ? ", " : "") + std::string(info.requiredPasses[i]);
      text += ")";
    }
  }
  return text;
}

std::optional<std::string> checkPassNames(const std::vector<std::string>& names) {
  for (const auto& name : names)
    if (!findPass(name)) return "unknown --pass '" + name + "' (valid: " + passNameList() + ")";
  return std::nullopt;
}

std::vector<const PassInfo*> selectPasses(const std::vector<std::string>& named, std::vector<std::string>* requiredBy) {
  const auto& registry = passRegistry();
  // Per registry entry: whether it runs, and for one only pulled in, the named pass that needed it.
  std::vector<bool> selected(registry.size(), false);
  std::vector<std::string> requester(registry.size());
  auto indexOf = [&](std::string_view name) {
    for (size_t i = 0; i < registry.size(); ++i)
      if (name == registry[i].name) return i;
    return registry.size();
  };
  // Named passes first (so a pass both named and required counts as named), then their
  // requirements, depth first; each pass is the requirement of the first named pass that needs it.
  std::vector<size_t> roots;
  for (const auto& name : named)
    if (size_t i = indexOf(name); i < registry.size() && !selected[i]) {
      selected[i] = true;
      roots.push_back(i);
    }
  for (size_t root : roots) {
    std::vector<size_t> stack = {root};
    while (!stack.empty()) {
      size_t at = stack.back();
      stack.pop_back();
      for (const char* required : registry[at].requiredPasses) {
        size_t r = indexOf(required);
        if (r == registry.size() || selected[r]) continue;
        selected[r] = true;
        requester[r] = registry[root].name;
        stack.push_back(r);
      }
    }
  }
  std::vector<const PassInfo*> passes;
  if (requiredBy) requiredBy->clear();
  for (size_t i = 0; i < registry.size(); ++i) {
    if (!selected[i]) continue;
    passes.push_back(&registry[i]);
    if (requiredBy) requiredBy->push_back(requester[i]);
  }
  return passes;
}

}  // namespace stereoshift
