// Reading a file whole, as every layer above reads shaders, manifests and outputs it compares.
#pragma once

#include <string>

namespace stereoshift {

// The bytes of the file at `path` into `contents`; false when it cannot be read.
bool readFile(const std::string& path, std::string* contents);

}  // namespace stereoshift
