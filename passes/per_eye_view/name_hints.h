// What a uniform's name hints about it, for per-eye-view: names only ever break a tie that
// structure cannot decide (a camera-like name where the next stage is not known; a light-like name
// vetoes a view vector, since a relief self-shadowing ray marches toward the light).
#pragma once

#include <string>

namespace stereoshift::per_eye_view {

enum class NameHint { Camera, Light, Neutral };

// Lower case, letters and digits only: `u_CameraPos` -> "ucamerapos".
std::string normalizedName(const std::string& name);
NameHint nameHint(const std::string& name);
const char* hintName(NameHint hint);  // "camera-like", "light-like", "neutral"
// An inverse view-projection matrix by its name: uInvViewProj, invViewProj, InverseViewProjection,
// g_ViewProjInv... A prefix of at most two characters is allowed (u, g, m, cb); longer ones
// (prevInvViewProj, shadowInvViewProj) name some other matrix.
bool namesInverseViewProjection(const std::string& name);

}  // namespace stereoshift::per_eye_view
