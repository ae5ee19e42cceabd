// Language detection: this turns a shader's file name and text (and the -x flag) into the language
// the front end parses it as, GLSL or HLSL, with the reason for the report.
//
// Many collections keep HLSL in files named by stage only (`hlsl/blur.frag`), so the name alone does
// not say. The order: -x wins; then a language extension (.hlsl .hlsli .fx .fxh, .glsl); then the
// text: a `#version` line makes it GLSL, otherwise a small scorer weighs constructs only one of the
// languages has (comments and strings skipped). GLSL stays the default when the text does not
// clearly say HLSL, so ESSL 100 / desktop 110 shaders without `#version` keep parsing as GLSL.
#pragma once

#include "core/shader.h"

#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// The language a file name states by its last extension (.hlsl .hlsli .fx .fxh -> HLSL, .glsl ->
// GLSL); nullopt for stage-only names (.vert, .frag, ...). Case-insensitive.
std::optional<SourceLanguage> languageFromFileName(const std::string& path);

// What the scorer found in a text. Each distinct sign counts once, with a weight: 3 for constructs
// that exist in one language only (cbuffer, `: SV_Position`, gl_Position, layout(...)), 2 for types
// and method calls that all but never occur in the other, 1 for intrinsics a shader may define
// itself (saturate, lerp, mix).
struct LanguageEvidence {
  bool hasVersion = false;  // a `#version` directive: GLSL, whatever else the text holds
  int hlslScore = 0, glslScore = 0;
  std::vector<std::string> hlslSigns, glslSigns;  // distinct signs, in order of first appearance
};
LanguageEvidence scoreLanguage(const std::string& text);

// HLSL only when the HLSL score reaches this and beats the GLSL score: one weak hint (a `lerp(`)
// is not enough to leave the GLSL default.
constexpr int kHlslScoreThreshold = 3;

struct LanguageDecision {
  SourceLanguage language = SourceLanguage::Glsl;
  LanguageSource source = LanguageSource::Content;
  std::string reason;  // one line: "-x hlsl", "file extension .hlsl", "#version directive", ...
};

// The language to parse `text` (from `path`) as; `flag` is -x.
LanguageDecision decideLanguage(const std::string& path, const std::string& text,
                                std::optional<SourceLanguage> flag);

// "extension", "flag" or "content": the report's `language_source`.
const char* languageSourceName(LanguageSource source);

}  // namespace stereoshift
