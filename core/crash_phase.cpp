// See crash_phase.h.
#include "core/crash_phase.h"

#include <sys/mman.h>

#include <csignal>
#include <cstdlib>
#include <cstring>

namespace stereoshift {

const char* const kGlslangGlslPhase = "the front end (glslang, parsing GLSL)";
const char* const kGlslangHlslPhase = "the front end (glslang, parsing HLSL)";
const char* const kRecompilePhase = "the re-compile check of the output (glslang, on the emitted text)";
const char* const kFoldedCopyPhase = "the analyses' folded copy (SPIRV-Tools' optimizer)";
const char* const kSpirvCrossPhase = "the back end (SPIRV-Cross, re-emitting the output)";
const char* const kMesaPhase = "Mesa's GLSL compiler (the OpenGL driver, checking the text)";

namespace {

CrashPhaseSlot* published = nullptr;
const char* current = nullptr;

void publish(const char* phase) {
  if (!published) return;
  if (!phase) {
    published->text[0] = '\0';
    return;
  }
  std::strncpy(published->text, phase, sizeof published->text - 1);
  published->text[sizeof published->text - 1] = '\0';
}

}  // namespace

CrashPhaseSlot* newSharedCrashPhaseSlot() {
  void* page = ::mmap(nullptr, sizeof(CrashPhaseSlot), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (page == MAP_FAILED) return nullptr;
  auto* slot = static_cast<CrashPhaseSlot*>(page);
  slot->text[0] = '\0';
  return slot;
}

void freeSharedCrashPhaseSlot(CrashPhaseSlot* slot) {
  if (slot) ::munmap(slot, sizeof(CrashPhaseSlot));
}

void publishCrashPhasesTo(CrashPhaseSlot* slot) {
  published = slot;
  publish(current);
}

std::string crashPhaseOf(const CrashPhaseSlot* slot) {
  if (!slot) return {};
  return std::string(slot->text, ::strnlen(slot->text, sizeof slot->text));
}

ScopedCrashPhase::ScopedCrashPhase(const char* phase) : previous_(current) {
  current = phase;
  publish(current);
  // Test-only: STEREOSHIFT_TEST_CRASH_IN names the start of a phase ("the back end"), and the process
  // dies in it as a third-party library would, so the tests of the crash ladder (cli/process_failure.h)
  // reach each rung whatever input crashes the packaged libraries today. Nothing else reads it.
  if (const char* crashIn = std::getenv("STEREOSHIFT_TEST_CRASH_IN");
      crashIn && *crashIn && std::strncmp(phase, crashIn, std::strlen(crashIn)) == 0)
    std::raise(SIGSEGV);
}

ScopedCrashPhase::~ScopedCrashPhase() {
  current = previous_;
  publish(current);
}

}  // namespace stereoshift
