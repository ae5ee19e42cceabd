// Where a conversion is, for the message about a process that died in it: a crash inside a
// third-party library (glslang's parsers overflow their stack or dereference null on some invalid
// inputs) kills the worker process, and its parent only sees the signal. The worker publishes the
// phase it is in to a page it shares with its parent; the parent reads it when the worker dies and
// says which part of the tool crashed (frontend/known_crashes.h names the input construct where it
// can be recognised). No dependencies: the worker pool (cli/worker_pool.cpp) links it on its own,
// and every layer marks its phases with it.
#pragma once

#include <string>

namespace stereoshift {

// One shared page's worth of text: the phase the worker is in, empty between phases.
struct CrashPhaseSlot {
  char text[248];
};

// A slot shared with processes forked after it (an anonymous shared mapping); null when the system
// refuses one. freeSharedCrashPhaseSlot unmaps it.
CrashPhaseSlot* newSharedCrashPhaseSlot();
void freeSharedCrashPhaseSlot(CrashPhaseSlot* slot);

// The slot this process publishes its phases to (the worker sets it once it is forked); null: none.
void publishCrashPhasesTo(CrashPhaseSlot* slot);
// The text of a slot: what the process was doing when it stopped; empty when it was in no phase.
std::string crashPhaseOf(const CrashPhaseSlot* slot);

// Marks the code in its scope as `phase` ("the front end (glslang, parsing HLSL)"); the previous
// phase comes back when it ends. `phase` must outlive the scope (a literal).
class ScopedCrashPhase {
 public:
  explicit ScopedCrashPhase(const char* phase);
  ~ScopedCrashPhase();
  ScopedCrashPhase(const ScopedCrashPhase&) = delete;
  ScopedCrashPhase& operator=(const ScopedCrashPhase&) = delete;

 private:
  const char* previous_;
};

// Phases named by the front end and the back end (compared by the driver to word its message).
extern const char* const kGlslangGlslPhase;
extern const char* const kGlslangHlslPhase;
extern const char* const kRecompilePhase;
extern const char* const kFoldedCopyPhase;
extern const char* const kSpirvCrossPhase;
extern const char* const kMesaPhase;

}  // namespace stereoshift
