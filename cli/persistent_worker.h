// How Bazel calls the tool, turned into the command line's own calls (bazel/stereoshift.bzl).
//
// - `@FILE` arguments: Bazel passes an action's command line in a params file, one argument per line
//   (its "multiline" format); they are expanded in place.
// - `--declared-input=PATH` (repeatable, normally inside the params file): the action's declared
//   inputs. With them the command must have --depfile, and every file the conversion read (its
//   sources and every #included file, as the depfile lists them) must be one of them; otherwise the
//   action fails and its outputs are removed. This keeps an action hermetic where no sandbox does
//   (a persistent worker, --spawn_strategy=local): an undeclared include cannot slip into a cached
//   or remotely executed action that worked locally only by chance.
// - `--persistent_worker`: the process becomes a Bazel persistent worker speaking the JSON worker
//   protocol (one WorkRequest object after another on standard input, one WorkResponse line each on
//   standard output). Each request's arguments run through the same entry as a command line, in one
//   long-lived converter process that keeps glslang's built-in tables warm across requests; the
//   worker itself only relays, so a request that crashes or hangs the converter costs that request
//   (an error response) and a fresh converter, never the worker.
#pragma once

#include "cli/depfile.h"  // parseDepfile: the action checks the depfile it wrote
#include "core/result.h"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace stereoshift {

// The command line's entry (argv[0] is the program name), as `main` has it.
using CommandLineEntry = std::function<int(int argc, char** argv)>;

// What `main` does: a persistent worker with --persistent_worker, the Bazel action path (params
// files, declared inputs) when an argument asks for it, else `entry` itself, unchanged.
int runToolEntry(int argc, char** argv, const CommandLineEntry& entry);

// Expands every `@FILE` argument into the lines of FILE; the error when one cannot be read.
Result<std::vector<std::string>> expandArgsFiles(const std::vector<std::string>& args);

// Runs one action (args[0] is the program name; params files already expanded): strips the
// --declared-input= arguments, runs `entry`, then checks the depfile against them (see above).
// Diagnostics go to `log`. Returns the exit status.
int runBazelAction(const std::vector<std::string>& args, const CommandLineEntry& entry, std::ostream& log);

// The worker loop over file descriptors (standard input and output for Bazel). `startupArgs` are
// the arguments the worker was started with besides --persistent_worker (Bazel passes an action's
// arguments outside its params file there, once): they come before each request's own. Returns the
// exit status: 0 at the end of the requests, 2 on a request that is not a WorkRequest.
int runPersistentWorker(const CommandLineEntry& entry, int requestsFd, int responsesFd,
                        const std::vector<std::string>& startupArgs = {});

}  // namespace stereoshift
