// The test-only hang (see test_hook.h).
#include "cli/test_hook.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace stereoshift {

void hangIfTestAsks(const std::string& path) {
  const char* hangOn = std::getenv("STEREOSHIFT_TEST_HANG");
  if (hangOn && *hangOn && std::filesystem::path(path).filename() == hangOn)
    while (true) ::pause();  // a conversion that never finishes
}

}  // namespace stereoshift
