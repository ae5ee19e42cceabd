// See name_hints.h.
#include "passes/per_eye_view/name_hints.h"

#include <cctype>
#include <cstring>

namespace stereoshift::per_eye_view {

std::string normalizedName(const std::string& name) {
  std::string out;
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

NameHint nameHint(const std::string& name) {
  std::string n = normalizedName(name);
  for (const char* word : {"light", "lamp", "sun", "shadow", "probe"})
    if (n.find(word) != std::string::npos) return NameHint::Light;
  for (const char* word : {"camera", "campos", "eyepos", "eyeorigin", "eyeworld", "viewpos", "vieworigin", "viewer"})
    if (n.find(word) != std::string::npos) return NameHint::Camera;
  return NameHint::Neutral;
}

bool namesInverseViewProjection(const std::string& name) {
  std::string n = normalizedName(name);
  for (const char* form : {"invviewproj", "inverseviewproj", "invviewprojection", "inverseviewprojection",
                           "viewprojinv", "viewprojinverse", "viewprojectioninv", "viewprojectioninverse",
                           "invvp", "viewprojectionmatrixinverse", "inverseviewprojectionmatrix",
                           "invviewprojectionmatrix", "invviewprojmatrix"})
    if (n.size() >= std::strlen(form) && n.compare(n.size() - std::strlen(form), std::string::npos, form) == 0 &&
        n.size() - std::strlen(form) <= 2)
      return true;
  return false;
}

const char* hintName(NameHint hint) {
  switch (hint) {
    case NameHint::Camera: return "camera-like";
    case NameHint::Light: return "light-like";
    case NameHint::Neutral: return "neutral";
  }
  return "?";
}

}  // namespace stereoshift::per_eye_view
