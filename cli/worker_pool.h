// A pool of forked worker processes for tree conversion. Each task runs in a worker process, so a
// task that crashes (glslang 12 overflows its stack on some inputs) or hangs costs only that task:
// the pool reports it, starts a fresh worker and goes on. Workers are forked after the parent has
// initialised glslang, so each one starts with the initialised library (copy-on-write) and keeps
// its own symbol tables warm across tasks; separate processes also share no locks.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace stereoshift {

// How a child process ended, from its wait status, for an error message: "crashed (signal 11,
// SIGSEGV)", "exited unexpectedly with status 3".
std::string describeExitStatus(int status);

struct TaskOutcome {
  bool completed = false;  // the task returned; `payload` is what it returned
  std::string payload;
  std::string failure;     // otherwise why not: "crashed (signal 11, SIGSEGV)", "timed out after 300 s"
  std::string phase;       // and what it was doing then (core/crash_phase.h): "the front end (glslang, ...)"
  double seconds = 0;      // wall time of the task
};

// Runs task(i) for every i in [0, count) on up to `workers` processes. `onDone` is called in the
// parent, once per task, in completion order. `timeoutSeconds` <= 0 means no limit. The parent must
// be single-threaded when this is called (it forks).
//
// `affinity` (optional, one key per task) groups tasks that share an expensive per-process set-up
// (glslang builds its built-in symbol tables once per dialect, per process): a worker keeps taking
// tasks of its last group; a free worker starts the untouched group with the most tasks; once every
// group is started, a free worker joins another's group only if that group's remaining work, timed
// in this run, pays for the set-up (otherwise it waits), so each set-up happens in as few workers
// as possible.
void runIsolated(size_t count, unsigned workers, double timeoutSeconds,
                 const std::function<std::string(size_t)>& task,
                 const std::function<void(size_t, TaskOutcome&&)>& onDone,
                 const std::vector<std::string>& affinity = {});

// The address space a worker forked after this may map (RLIMIT_AS; 0: no limit, the default), so
// that one input cannot take the machine down: a task whose allocation fails past it ends its worker,
// and its outcome says it ran out of memory, with the limit. Not applied under AddressSanitizer,
// whose shadow memory is mapped address space far beyond any such limit.
void setWorkerMemoryLimit(uint64_t bytes);

// Runs one task in a forked child and waits for it: the same isolation for a single conversion.
TaskOutcome runIsolatedOnce(const std::function<std::string()>& task, double timeoutSeconds);

}  // namespace stereoshift
