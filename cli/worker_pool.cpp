#include "cli/worker_pool.h"

#include "cli/fd_io.h"
#include "core/crash_phase.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <new>
#include <vector>

namespace stereoshift {

namespace {

uint64_t workerMemoryLimit = 0;
// A worker whose task ran out of memory exits with this status (see workerLoop).
constexpr int kOutOfMemoryExit = 86;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kUnderAddressSanitizer = true;
#else
constexpr bool kUnderAddressSanitizer = false;
#endif
#else
constexpr bool kUnderAddressSanitizer = false;
#endif

}  // namespace

void setWorkerMemoryLimit(uint64_t bytes) { workerMemoryLimit = bytes; }

std::string describeExitStatus(int status) {
  if (WIFSIGNALED(status)) {
    int sig = WTERMSIG(status);
    const char* name = sigabbrev_np(sig);
    return "crashed (signal " + std::to_string(sig) + (name ? std::string(", SIG") + name : std::string()) + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemoryExit)
    return "ran out of memory (past the per-job limit of " + std::to_string(workerMemoryLimit >> 20) +
           " MiB, --job-memory)";
  if (WIFEXITED(status)) return "exited unexpectedly with status " + std::to_string(WEXITSTATUS(status));
  return "stopped unexpectedly";
}

namespace {

using Clock = std::chrono::steady_clock;

// The child's side: reads task indices, answers with a size-prefixed payload, until EOF.
[[noreturn]] void workerLoop(int requests, int results, const std::function<std::string(size_t)>& task) {
  uint64_t index;
  while (readAll(requests, &index, sizeof index)) {
    std::string payload;
    try {
      payload = task(static_cast<size_t>(index));
    } catch (const std::bad_alloc&) {
      ::_exit(kOutOfMemoryExit);  // past the memory limit: the parent reports it, the pool starts another
    }
    uint64_t size = payload.size();
    if (!writeAll(results, &size, sizeof size) || !writeAll(results, payload.data(), payload.size())) break;
  }
  ::_exit(0);  // no atexit handlers or static destructors: they belong to the parent
}

struct Worker {
  pid_t pid = -1;
  int requests = -1;  // parent writes task indices
  int results = -1;   // parent reads payloads
  bool busy = false;
  size_t task = 0;
  Clock::time_point started;
  std::string buffer;  // size prefix + payload as it arrives
  std::string group;   // affinity of its last task
  std::vector<std::string> warmGroups;  // groups this process has run a task of
  bool firstOfGroup = false;            // its current task is its first of `group` (pays the set-up)
  CrashPhaseSlot* phase = nullptr;      // shared with the process: the phase its task is in
};

// `others`: the pool, whose parent-side pipe ends a new child must not keep open (a child holding
// another worker's request pipe would stop that worker from ever seeing EOF).
bool startWorker(Worker& w, const std::vector<Worker>& others, const std::function<std::string(size_t)>& task) {
  int toChild[2], fromChild[2];
  if (::pipe(toChild) != 0) return false;
  if (::pipe(fromChild) != 0) {
    ::close(toChild[0]);
    ::close(toChild[1]);
    return false;
  }
  CrashPhaseSlot* phase = newSharedCrashPhaseSlot();  // null without one: failures then name no phase
  pid_t pid = ::fork();
  if (pid < 0) {
    for (int fd : {toChild[0], toChild[1], fromChild[0], fromChild[1]}) ::close(fd);
    freeSharedCrashPhaseSlot(phase);
    return false;
  }
  if (pid == 0) {
    publishCrashPhasesTo(phase);
    if (workerMemoryLimit && !kUnderAddressSanitizer) {
      struct rlimit limit {};
      limit.rlim_cur = limit.rlim_max = workerMemoryLimit;
      ::setrlimit(RLIMIT_AS, &limit);
    }
    ::close(toChild[1]);
    ::close(fromChild[0]);
    for (const auto& other : others)
      if (&other != &w)
        for (int fd : {other.requests, other.results})
          if (fd >= 0) ::close(fd);
    workerLoop(toChild[0], fromChild[1], task);
  }
  ::close(toChild[0]);
  ::close(fromChild[1]);
  w = Worker{};
  w.pid = pid;
  w.phase = phase;
  w.requests = toChild[1];
  w.results = fromChild[0];
  return true;
}

// Closes the worker's pipes (it sees EOF and exits), kills it first when `kill`, and reaps it;
// returns its wait status.
int stopWorker(Worker& w, bool kill) {
  if (w.requests >= 0) ::close(w.requests);
  if (w.results >= 0) ::close(w.results);
  w.requests = w.results = -1;
  int status = 0;
  if (w.pid > 0) {
    if (kill) ::kill(w.pid, SIGKILL);
    while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  w.pid = -1;
  w.busy = false;
  freeSharedCrashPhaseSlot(w.phase);
  w.phase = nullptr;
  return status;
}

// Reaps a worker that closed its pipe mid-task and says why it died; `phase` gets what it was
// doing then (crash_phase.h), empty when it was in no marked phase.
std::string reapDead(Worker& w, std::string* phase) {
  *phase = crashPhaseOf(w.phase);
  return describeExitStatus(stopWorker(w, false));
}

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

namespace {

// One runIsolated call: the pool, the pending tasks and what the scheduler has learnt so far.
//
// Scheduling by affinity group (glslang builds its built-in tables once per dialect per process):
// a worker keeps to its group; a free worker starts the untouched group with the most pending
// tasks (largest first balances the workers' loads); when every group has been started it joins
// another worker's group only when that pays for the group's set-up. The set-up cost is learnt
// while running: a worker's first task of a group takes set-up + t, its later ones t.
class IsolatedRun {
 public:
  IsolatedRun(size_t count, unsigned workers, double timeoutSeconds, const std::function<std::string(size_t)>& task,
              const std::function<void(size_t, TaskOutcome&&)>& onDone, const std::vector<std::string>& affinity)
      : count_(count), timeoutSeconds_(timeoutSeconds), task_(task), onDone_(onDone), affinity_(affinity),
        pool_(std::max(1u, std::min<unsigned>(workers, static_cast<unsigned>(count)))) {
    for (size_t i = 0; i < count; ++i) pending_.push_back(i);
    if (grouped())
      for (const auto& group : affinity) ++pendingOf_[group];
  }

  void run() {
    for (auto& w : pool_)
      if (!dispatch(w)) break;
    while (waitForWorkers()) {
    }
    for (auto& w : pool_)
      if (w.pid > 0) stopWorker(w, false);
  }

 private:
  struct GroupTimes {
    double firstSeconds = -1;  // quickest first task of the group in a worker
    double restSeconds = 0;    // later tasks: total and count
    size_t restCount = 0;
  };

  bool grouped() const { return affinity_.size() == count_; }

  void fail(size_t index, std::string why, double seconds, std::string phase = {}) {
    TaskOutcome outcome;
    outcome.failure = std::move(why);
    outcome.phase = std::move(phase);
    outcome.seconds = seconds;
    onDone_(index, std::move(outcome));
  }

  void failDead(size_t index, Worker& w, double seconds) {
    std::string phase;
    std::string why = reapDead(w, &phase);
    fail(index, why, seconds, phase);
  }

  bool started(const std::string& group) const {
    return std::find(groupsStarted_.begin(), groupsStarted_.end(), group) != groupsStarted_.end();
  }

  // Whether one more worker on `group` finishes it sooner: with w workers on it and p tasks of t
  // seconds left, a newcomer paying set-up s finishes at (p·t + s)/(w + 1), against p·t/w without it.
  bool worthJoining(const std::string& group) {
    const GroupTimes& times = groupTimes_[group];
    if (times.firstSeconds < 0 || times.restCount == 0) return true;  // nothing learnt yet: join
    double t = times.restSeconds / static_cast<double>(times.restCount);
    double setup = std::max(0.0, times.firstSeconds - t);
    size_t onIt = static_cast<size_t>(
        std::count_if(pool_.begin(), pool_.end(), [&](const Worker& o) { return o.busy && o.group == group; }));
    return onIt == 0 || static_cast<double>(pendingOf_[group]) * t > static_cast<double>(onIt) * setup;
  }

  // The pending task `w` should take next, or pending_.end() when it had better stay idle.
  std::deque<size_t>::iterator choose(const Worker& w) {
    if (!grouped()) return pending_.begin();
    auto same = std::find_if(pending_.begin(), pending_.end(), [&](size_t i) { return affinity_[i] == w.group; });
    if (same != pending_.end()) return same;
    auto firstOf = [&](const std::string& group) {
      return std::find_if(pending_.begin(), pending_.end(), [&](size_t i) { return affinity_[i] == group; });
    };
    const std::string* fresh = nullptr;
    const std::string* largest = nullptr;
    for (const auto& [group, n] : pendingOf_) {
      if (n == 0) continue;
      if (!started(group) && (!fresh || n > pendingOf_[*fresh])) fresh = &group;
      if (!largest || n > pendingOf_[*largest]) largest = &group;
    }
    if (fresh) return firstOf(*fresh);
    if (!largest) return pending_.end();
    // Every group is started: join the one with the most pending tasks, if that pays (or if nobody
    // else would run it).
    bool anotherBusy = std::any_of(pool_.begin(), pool_.end(), [&](const Worker& o) { return &o != &w && o.busy; });
    return !anotherBusy || worthJoining(*largest) ? firstOf(*largest) : pending_.end();
  }

  // Hands the next task to `w`, starting it first when needed; false when it gets none.
  bool dispatch(Worker& w) {
    while (!pending_.empty()) {
      if (w.pid < 0 && !startWorker(w, pool_, task_)) {
        size_t index = pending_.front();
        pending_.pop_front();
        if (grouped()) --pendingOf_[affinity_[index]];
        fail(index, std::string("cannot start a worker process: ") + std::strerror(errno), 0);
        continue;
      }
      auto next = choose(w);
      if (next == pending_.end()) return false;
      size_t index = *next;
      pending_.erase(next);
      w.firstOfGroup = false;
      if (grouped()) {
        --pendingOf_[affinity_[index]];
        w.group = affinity_[index];
        w.firstOfGroup = std::find(w.warmGroups.begin(), w.warmGroups.end(), w.group) == w.warmGroups.end();
        if (w.firstOfGroup) w.warmGroups.push_back(w.group);
        if (!started(w.group)) groupsStarted_.push_back(w.group);
      }
      uint64_t wire = index;
      w.busy = true;
      w.task = index;
      w.started = Clock::now();
      w.buffer.clear();
      if (writeAll(w.requests, &wire, sizeof wire)) return true;
      failDead(index, w, 0);  // died between tasks
    }
    return false;
  }

  void learn(const Worker& w, double seconds) {
    if (!grouped()) return;
    GroupTimes& times = groupTimes_[w.group];
    if (w.firstOfGroup) {
      times.firstSeconds = times.firstSeconds < 0 ? seconds : std::min(times.firstSeconds, seconds);
    } else {
      times.restSeconds += seconds;
      ++times.restCount;
    }
  }

  // Workers left idle by choose() are offered work again whenever a task ends (estimates change,
  // and the last busy worker may have died).
  void dispatchIdle() {
    for (auto& o : pool_)
      if (!o.busy && o.pid > 0 && !pending_.empty()) dispatch(o);
  }

  // One poll over the busy workers and what it found; false when none is busy (or poll failed).
  bool waitForWorkers() {
    std::vector<pollfd> fds;
    std::vector<Worker*> owners;
    for (auto& w : pool_)
      if (w.busy) {
        fds.push_back({w.results, POLLIN, 0});
        owners.push_back(&w);
      }
    if (fds.empty()) return false;
    int waitMs = timeoutSeconds_ > 0 ? 100 : -1;
    int ready = ::poll(fds.data(), fds.size(), waitMs);
    if (ready < 0 && errno != EINTR) return false;
    for (size_t k = 0; k < fds.size(); ++k) {
      Worker& w = *owners[k];
      if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) {
        readFrom(w);
      } else if (timeoutSeconds_ > 0 && secondsSince(w.started) > timeoutSeconds_) {
        stopLate(w);
      }
    }
    return true;
  }

  // What a worker's pipe holds: more of its answer, the whole answer, or the end (it died).
  void readFrom(Worker& w) {
    char chunk[65536];
    ssize_t n = ::read(w.results, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) return;
    if (n <= 0) {  // EOF mid-task: the worker died
      size_t index = w.task;
      double seconds = secondsSince(w.started);
      failDead(index, w, seconds);
      dispatch(w);
      dispatchIdle();
      return;
    }
    w.buffer.append(chunk, static_cast<size_t>(n));
    uint64_t size = 0;
    if (w.buffer.size() < sizeof size) return;
    std::memcpy(&size, w.buffer.data(), sizeof size);
    if (w.buffer.size() - sizeof size < size) return;
    TaskOutcome outcome;
    outcome.completed = true;
    outcome.payload = w.buffer.substr(sizeof size, size);
    outcome.seconds = secondsSince(w.started);
    size_t index = w.task;
    w.busy = false;
    w.buffer.clear();
    learn(w, outcome.seconds);
    // The worker gets its next task before the parent handles this result (writing files), so the
    // two overlap.
    dispatch(w);
    dispatchIdle();
    onDone_(index, std::move(outcome));
  }

  // A task past the time limit: its worker is killed and replaced.
  void stopLate(Worker& w) {
    size_t index = w.task;
    double seconds = secondsSince(w.started);
    std::string phase = crashPhaseOf(w.phase);
    stopWorker(w, true);
    char text[64];
    std::snprintf(text, sizeof text, "timed out after %g s", timeoutSeconds_);
    fail(index, text, seconds, phase);
    dispatch(w);
    dispatchIdle();
  }

  const size_t count_;
  const double timeoutSeconds_;
  const std::function<std::string(size_t)>& task_;
  const std::function<void(size_t, TaskOutcome&&)>& onDone_;
  const std::vector<std::string>& affinity_;
  std::deque<size_t> pending_;
  std::vector<Worker> pool_;
  std::map<std::string, GroupTimes> groupTimes_;
  std::vector<std::string> groupsStarted_;
  std::map<std::string, size_t> pendingOf_;  // pending tasks per group
};

}  // namespace

void runIsolated(size_t count, unsigned workers, double timeoutSeconds,
                 const std::function<std::string(size_t)>& task,
                 const std::function<void(size_t, TaskOutcome&&)>& onDone,
                 const std::vector<std::string>& affinity) {
  if (count == 0) return;
  // A dead worker's request pipe must not kill the parent.
  struct sigaction ignore {}, previous{};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGPIPE, &ignore, &previous);
  IsolatedRun(count, workers, timeoutSeconds, task, onDone, affinity).run();
  ::sigaction(SIGPIPE, &previous, nullptr);
}

TaskOutcome runIsolatedOnce(const std::function<std::string()>& task, double timeoutSeconds) {
  TaskOutcome result;
  runIsolated(1, 1, timeoutSeconds, [&](size_t) { return task(); },
              [&](size_t, TaskOutcome&& outcome) { result = std::move(outcome); });
  return result;
}

}  // namespace stereoshift
