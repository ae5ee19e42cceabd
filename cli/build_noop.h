// The no-op record of `stereoshift build`: this turns a rebuild in which nothing changed into a stat
// call per file, without planning the tree, reading a shader or loading the cache again.
//
// After a run that ended without an error, the build records beside its outputs what a rebuild with
// nothing changed would write and print (the report and the depfile of a run in which every
// pipeline is up to date, its messages: computed then, from the plan and the cache that run left)
// and what would make a rebuild differ: the command line (with the tool's identity and the working
// directory) and the stamp (size, inode, modification and status-change times) of every file and
// directory of the source tree, of every dependency outside it, and of every file of the output
// tree. A rebuild whose command line and every stamp are the recorded ones writes the
// recorded report and depfile (where their bytes differ), prints the recorded messages and stops.
// Anything else (an edit, a new or removed file anywhere in either tree, another option, another
// build of the tool) finds a stamp or the key changed, and the build runs as it always did.
//
// The status-change time moves with every change of a file and cannot be set back; but the file
// system's clock is coarse (a few milliseconds), so a file changed again within the tick of its
// recorded stamp would keep it. The record is therefore taken against the clock: a marker file is
// written first, and a stamp whose status-change time is not strictly older than the marker's
// (a file that changed within the current tick or later) is not recorded; the recording waits for
// the next tick and tries again, and gives up (no record: the next rebuild plans as before) after
// a few tries.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace stereoshift {

// What a rebuild with nothing changed would write and print.
struct NoopOutcome {
  std::filesystem::path reportPath;
  std::string reportText;
  std::filesystem::path depfilePath;  // empty: no depfile
  std::string depfileText;
  std::string messages;  // standard error, as the rebuild would print it
};

// The key of a rebuild: the tool's identity, the working directory, the command line.
std::string noopRunKey(const std::vector<std::string>& commandLine);

// Records `outcome` and the stamps (see above) in `outDir`; `dependencies` are the report's (every
// input and included file). A failure to record only leaves the next rebuild to plan.
void recordNoop(const std::filesystem::path& source, const std::filesystem::path& outDir, const std::string& runKey,
                const NoopOutcome& outcome, const std::vector<std::string>& dependencies);

// Before planning: whether the recorded rebuild applies (same key, every stamp the recorded one);
// then its report and depfile are written where their bytes differ and its messages printed.
bool replayNoop(const std::filesystem::path& outDir, const std::string& runKey);

// Removes the record (a run that plans is under way: its outcome is not known yet).
void forgetNoop(const std::filesystem::path& outDir);

}  // namespace stereoshift
