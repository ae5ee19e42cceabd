// See mesa_compiler.h.
#include "transpiler/frontend/mesa_compiler.h"

#include "core/crash_phase.h"
#include "transpiler/frontend/glsl_version.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace stereoshift {

namespace {

// The few EGL and GL names used, declared here so that no EGL or GL headers are needed to build:
// the values are the registries' (EGL 1.5, EGL_MESA_platform_surfaceless, OpenGL 2.0 / 4.3).
using EglDisplay = void*;
using EglContext = void*;
using EglInt = int32_t;
constexpr unsigned kEglPlatformSurfacelessMesa = 0x31DD;
constexpr unsigned kEglOpenGlApi = 0x30A2;
constexpr EglInt kEglContextMajorVersion = 0x3098, kEglContextMinorVersion = 0x30FB,
                 kEglContextOpenGlProfileMask = 0x30FD, kEglCompatibilityProfileBit = 0x2, kEglNone = 0x3038;
constexpr unsigned kGlCompileStatus = 0x8B81, kGlInfoLogLength = 0x8B84, kGlRenderer = 0x1F01, kGlVersion = 0x1F02;

unsigned glShaderType(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return 0x8B31;
    case Stage::Fragment: return 0x8B30;
    case Stage::Geometry: return 0x8DD9;
    case Stage::TessControl: return 0x8E88;
    case Stage::TessEvaluation: return 0x8E87;
    case Stage::Compute: return 0x91B9;
    default: return 0;
  }
}

// The loaded library and the context, made on the first call and kept for the process.
struct Mesa {
  std::string unavailable;  // non-empty: no verdict can be had, and why
  std::string driver;
  unsigned (*createShader)(unsigned) = nullptr;
  void (*deleteShader)(unsigned) = nullptr;
  void (*shaderSource)(unsigned, int, const char* const*, const int*) = nullptr;
  void (*compileShader)(unsigned) = nullptr;
  void (*getShaderiv)(unsigned, unsigned, int*) = nullptr;
  void (*getShaderInfoLog)(unsigned, int, int*, char*) = nullptr;
};

template <typename F>
F symbol(void* library, void* (*getProc)(const char*), const char* name) {
  void* found = getProc ? getProc(name) : nullptr;
  if (!found && library) found = ::dlsym(library, name);
  return reinterpret_cast<F>(found);
}

Mesa load() {
  Mesa m;
  const char* chosen = std::getenv("STEREOSHIFT_EGL_LIBRARY");
  const std::string path = chosen && *chosen ? chosen : "libEGL.so.1";
  if (path == "none") {
    m.unavailable = "no libEGL (STEREOSHIFT_EGL_LIBRARY=none)";
    return m;
  }
  // llvmpipe on every machine: a GPU's driver would be another compiler, with other answers.
  ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    m.unavailable = "cannot load " + path;
    return m;
  }
  auto getProc = reinterpret_cast<void* (*)(const char*)>(::dlsym(library, "eglGetProcAddress"));
  auto getPlatformDisplay = symbol<EglDisplay (*)(unsigned, void*, const intptr_t*)>(library, getProc, "eglGetPlatformDisplay");
  auto initialize = symbol<unsigned (*)(EglDisplay, EglInt*, EglInt*)>(library, getProc, "eglInitialize");
  auto bindApi = symbol<unsigned (*)(unsigned)>(library, getProc, "eglBindAPI");
  auto createContext = symbol<EglContext (*)(EglDisplay, void*, EglContext, const EglInt*)>(library, getProc, "eglCreateContext");
  auto makeCurrent = symbol<unsigned (*)(EglDisplay, void*, void*, EglContext)>(library, getProc, "eglMakeCurrent");
  if (!getProc || !getPlatformDisplay || !initialize || !bindApi || !createContext || !makeCurrent) {
    m.unavailable = path + " lacks the EGL 1.5 entry points";
    return m;
  }
  EglDisplay display = getPlatformDisplay(kEglPlatformSurfacelessMesa, nullptr, nullptr);
  EglInt major = 0, minor = 0;
  if (!display || !initialize(display, &major, &minor)) {
    m.unavailable = "no surfaceless EGL display (Mesa's EGL with EGL_MESA_platform_surfaceless)";
    return m;
  }
  if (!bindApi(kEglOpenGlApi)) {
    m.unavailable = "EGL has no OpenGL API";
    return m;
  }
  const EglInt attributes[] = {kEglContextMajorVersion, 4, kEglContextMinorVersion, 5, kEglContextOpenGlProfileMask,
                               kEglCompatibilityProfileBit, kEglNone};
  EglContext context = createContext(display, nullptr, nullptr, attributes);
  if (!context || !makeCurrent(display, nullptr, nullptr, context)) {
    m.unavailable = "no OpenGL 4.5 compatibility context without a surface (Mesa's llvmpipe: libgl1-mesa-dri)";
    return m;
  }
  m.createShader = symbol<decltype(m.createShader)>(library, getProc, "glCreateShader");
  m.deleteShader = symbol<decltype(m.deleteShader)>(library, getProc, "glDeleteShader");
  m.shaderSource = symbol<decltype(m.shaderSource)>(library, getProc, "glShaderSource");
  m.compileShader = symbol<decltype(m.compileShader)>(library, getProc, "glCompileShader");
  m.getShaderiv = symbol<decltype(m.getShaderiv)>(library, getProc, "glGetShaderiv");
  m.getShaderInfoLog = symbol<decltype(m.getShaderInfoLog)>(library, getProc, "glGetShaderInfoLog");
  auto getString = symbol<const char* (*)(unsigned)>(library, getProc, "glGetString");
  if (!m.createShader || !m.deleteShader || !m.shaderSource || !m.compileShader || !m.getShaderiv ||
      !m.getShaderInfoLog || !getString) {
    m.unavailable = "the OpenGL context lacks the shader entry points";
    return m;
  }
  const char* version = getString(kGlVersion);
  const char* renderer = getString(kGlRenderer);
  m.driver = std::string(version ? version : "OpenGL") + " (" + (renderer ? renderer : "unknown renderer") + ")";
  return m;
}

MesaVerdict compileOnce(Mesa& m, const std::string& source, unsigned type, const std::string& file);

Mesa& mesa() {
  static Mesa loaded = [] {
    ScopedCrashPhase phase(kMesaPhase);
    return load();
  }();
  return loaded;
}

// Mesa's info log, one `0:L(C): error: message` line an error, as diagnostics at `file`. A line in
// another form is kept whole, at no location.
std::vector<Diagnostic> readInfoLog(const std::string& log, const std::string& file) {
  std::vector<Diagnostic> errors;
  size_t at = 0;
  while (at < log.size()) {
    size_t end = log.find('\n', at);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(at, end - at);
    at = end + 1;
    if (line.find("error") == std::string::npos) continue;
    Diagnostic d;
    d.file = file;
    int source = 0, number = 0, column = 0, read = 0;
    if (std::sscanf(line.c_str(), "%d:%d(%d): %n", &source, &number, &column, &read) == 3 && read > 0) {
      d.line = std::max(0, number);
      d.column = column;
      d.message = line.substr(static_cast<size_t>(read));
      if (d.message.rfind("error: ", 0) == 0) d.message = d.message.substr(7);
    } else {
      d.message = line;
    }
    d.message = "Mesa: " + d.message;
    errors.push_back(std::move(d));
  }
  return errors;
}

}  // namespace

MesaVerdict compileWithMesa(const std::string& text, Stage stage, const std::string& file,
                            std::optional<std::string> versionIfNone) {
  MesaVerdict verdict;
  Mesa& m = mesa();
  if (!m.unavailable.empty()) {
    verdict.why = m.unavailable;
    return verdict;
  }
  verdict.driver = m.driver;
  const unsigned type = glShaderType(stage);
  if (!type) {
    verdict.why = std::string("OpenGL has no ") + stageName(stage) + " stage";
    return verdict;
  }
  ScopedCrashPhase phase(kMesaPhase);
  if (findVersion(text).begin == std::string::npos) {
    // Text without #version is read at the version a loader prepends; Mesa numbers the line after
    // `#line 0` as 1, so every line keeps its number.
    static const char* const ladder[] = {"110", "100", "120", "130", "140", "150", "330", "400", "410",
                                         "420", "430", "440", "450", "300 es", "310 es", "320 es"};
    std::vector<std::string> versions;
    if (versionIfNone) versions.push_back(*versionIfNone);
    for (const char* version : ladder)
      if (!versionIfNone || *versionIfNone != version) versions.emplace_back(version);
    MesaVerdict first;
    for (const auto& version : versions) {
      MesaVerdict tried = compileOnce(m, "#version " + version + "\n#line 0\n" + text, type, file);
      tried.driver = m.driver;
      if (tried.kind == MesaVerdict::Kind::Compiled) {
        tried.version = version;
        return tried;
      }
      if (&version == &versions.front()) first = std::move(tried);
    }
    return first;
  }
  MesaVerdict once = compileOnce(m, text, type, file);
  once.driver = m.driver;
  return once;
}

namespace {

MesaVerdict compileOnce(Mesa& m, const std::string& source, unsigned type, const std::string& file) {
  MesaVerdict verdict;
  const char* strings[] = {source.c_str()};
  const int lengths[] = {static_cast<int>(source.size())};
  unsigned shader = m.createShader(type);
  m.shaderSource(shader, 1, strings, lengths);
  m.compileShader(shader);
  int compiled = 0, logLength = 0;
  m.getShaderiv(shader, kGlCompileStatus, &compiled);
  m.getShaderiv(shader, kGlInfoLogLength, &logLength);
  std::string log(static_cast<size_t>(std::max(logLength, 0)), '\0');
  if (logLength > 0) m.getShaderInfoLog(shader, logLength, nullptr, log.data());
  m.deleteShader(shader);
  if (auto nul = log.find('\0'); nul != std::string::npos) log.resize(nul);
  if (compiled) {
    verdict.kind = MesaVerdict::Kind::Compiled;
    return verdict;
  }
  // A version this Mesa does not have is no verdict on the shader.
  if (log.find("is not supported. Supported versions are") != std::string::npos) {
    verdict.why = "this Mesa (" + m.driver + ") does not have the shader's GLSL version";
    return verdict;
  }
  verdict.kind = MesaVerdict::Kind::Refused;
  verdict.errors = readInfoLog(log, file);
  if (verdict.errors.empty()) verdict.errors.push_back({Severity::Error, file, 0, 0, "Mesa: " + log});
  return verdict;
}

}  // namespace

}  // namespace stereoshift
