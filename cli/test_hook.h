// Test-only hook: when the environment variable STEREOSHIFT_TEST_HANG names a file (its file name,
// no directory), reading that file never finishes (the process sleeps until it is killed), so the
// tests of --timeout and `build --job-timeout` reach any limit whatever the machine's speed. This
// runs where the conversion runs: in the forked child or build worker, never in build's parent.
// Kept apart so that nothing else in the product looks at the variable.
#pragma once

#include <string>

namespace stereoshift {

// Never returns when STEREOSHIFT_TEST_HANG names `path`'s file name; else returns at once.
void hangIfTestAsks(const std::string& path);

}  // namespace stereoshift
