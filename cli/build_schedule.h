// The schedule of `stereoshift build`: runs the jobs the cache could not answer. Copy-through passes
// (mono, post, UI) are copied in the parent; conversions run in worker processes (a crash or a hang
// costs one pipeline, not the run), grouped by dialect so that glslang's per-dialect set-up is paid
// in as few workers as possible, and each output is written atomically as it arrives.
#pragma once

#include "cli/build_cache.h"
#include "cli/build_job.h"
#include "cli/build_plan.h"

#include <string>
#include <vector>

namespace stereoshift {

// Copies the sources of every copy-through job to its outputs (the bytes of the source, no front end).
void copyThroughPasses(const Plan& plan, std::vector<JobResult>& results);

struct ScheduleOptions {
  int jobs = 0;                    // worker processes (0: one per core)
  double jobTimeoutSeconds = 300;  // a pipeline that takes longer is killed and reported (<= 0: no limit)
  bool progress = true;            // a progress bar on a terminal (-q: none)
};

// Converts plan.jobs[i] for every i in `toConvert` in worker processes, writes their outputs, and
// records in `next` the jobs that converted, or failed with diagnostics the same inputs repeat.
// Shows progress on a terminal when options.progress.
void convertInWorkers(const Plan& plan, const std::vector<size_t>& toConvert, const std::string& tool,
                      const ScheduleOptions& options, std::vector<JobResult>& results, Cache& next);

// Copies every file that a written output still #includes (a copied-through or spliced output keeps
// its source's #include lines; a re-emitted one carries the code), and what those include, from the
// source tree to the same place under the output directory, unless it is there with the same bytes:
// the output tree builds on its own. Files outside the tree (an -I directory elsewhere) stay where
// they are. Returns the output paths (in path order); a failure goes to the log of the job that
// needed the file and counts as its error.
std::vector<std::filesystem::path> copyIncludedFiles(const Plan& plan, std::vector<JobResult>& results);

}  // namespace stereoshift
