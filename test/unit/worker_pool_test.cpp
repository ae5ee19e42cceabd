// The worker pool's scheduling by affinity group, with tasks that imitate glslang: the first task of
// a group in a process pays a set-up (the built-in symbol tables), later ones do not.
#include "cli/worker_pool.h"
#include "core/crash_phase.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace stereoshift {
namespace {

using std::chrono::milliseconds;

struct PoolRun {
  std::map<std::string, std::set<std::string>> processesOf;  // group -> pids that ran its tasks
  size_t completed = 0;
};

// `groups[i]` is task i's group; every task sleeps `taskMs`, plus `setupMs` the first time its group
// runs in a process. Each task answers with its process id.
PoolRun runGroups(const std::vector<std::string>& groups, int setupMs, int taskMs, unsigned workers) {
  PoolRun run;
  auto task = [&](size_t i) {
    static std::set<std::string> warm;  // per worker process: each is a fork of this one
    if (warm.insert(groups[i]).second) std::this_thread::sleep_for(milliseconds(setupMs));
    std::this_thread::sleep_for(milliseconds(taskMs));
    return std::to_string(::getpid());
  };
  runIsolated(groups.size(), workers, 0, task, [&](size_t i, TaskOutcome&& outcome) {
    ASSERT_TRUE(outcome.completed) << outcome.failure;
    run.processesOf[groups[i]].insert(outcome.payload);
    ++run.completed;
  }, groups);
  return run;
}

TEST(WorkerPool, WaitsRatherThanPayingASetUpTheRemainingWorkDoesNotCover) {
  // Two workers: one takes the 12-task group, the other the 5-task one. When the second is done
  // (~550 ms), ~6 tasks of 30 ms are left in the first group: 180 ms of work against a 400 ms set-up,
  // so it must not join (an always-steal scheduler runs the big group in both processes).
  std::vector<std::string> groups(12, "big");
  groups.insert(groups.end(), 5, "small");
  PoolRun run = runGroups(groups, 400, 30, 2);
  EXPECT_EQ(run.completed, groups.size());
  EXPECT_EQ(run.processesOf["big"].size(), 1u);
  EXPECT_EQ(run.processesOf["small"].size(), 1u);
  EXPECT_NE(*run.processesOf["big"].begin(), *run.processesOf["small"].begin());
}

TEST(WorkerPool, JoinsAGroupWhoseRemainingWorkPaysForTheSetUp) {
  // 40 tasks of 20 ms left against a 50 ms set-up: the free worker joins, so the big group runs in
  // both processes.
  std::vector<std::string> groups(40, "big");
  groups.push_back("small");
  PoolRun run = runGroups(groups, 50, 20, 2);
  EXPECT_EQ(run.completed, groups.size());
  EXPECT_EQ(run.processesOf["big"].size(), 2u);
}

TEST(WorkerPool, EveryTaskRunsOnceWithOneWorker) {
  std::vector<std::string> groups = {"a", "b", "a", "c", "b", "a"};
  PoolRun run = runGroups(groups, 0, 1, 1);
  EXPECT_EQ(run.completed, groups.size());
  for (const auto& [group, pids] : run.processesOf) EXPECT_EQ(pids.size(), 1u) << group;
}

}  // namespace
}  // namespace stereoshift

// A task that dies inside a marked phase (core/crash_phase.h): its outcome names the signal and
// the phase; the worker after it starts with no phase; a task that dies outside every phase names none.
namespace stereoshift {
namespace {

TEST(WorkerPool, ADeadTaskNamesThePhaseItDiedIn) {
  std::map<size_t, TaskOutcome> outcomes;
  runIsolated(
      3, 1, 0,
      [](size_t i) -> std::string {
        if (i == 0) {
          ScopedCrashPhase phase("the front end (a test phase)");
          ::raise(SIGKILL);  // a signal no sanitizer intercepts (ASan reports SIGSEGV and exits 1)
        }
        if (i == 1) {
          { ScopedCrashPhase done("a phase that ended"); }
          ::raise(SIGKILL);
        }
        return "ok";
      },
      [&](size_t i, TaskOutcome&& o) { outcomes[i] = std::move(o); });
  ASSERT_EQ(outcomes.size(), 3u);
  EXPECT_FALSE(outcomes[0].completed);
  EXPECT_EQ(outcomes[0].failure, "crashed (signal 9, SIGKILL)");
  EXPECT_EQ(outcomes[0].phase, "the front end (a test phase)");
  EXPECT_FALSE(outcomes[1].completed);
  EXPECT_EQ(outcomes[1].failure, "crashed (signal 9, SIGKILL)");
  EXPECT_EQ(outcomes[1].phase, "");
  EXPECT_TRUE(outcomes[2].completed);
  EXPECT_EQ(outcomes[2].phase, "");
}

}  // namespace
}  // namespace stereoshift
