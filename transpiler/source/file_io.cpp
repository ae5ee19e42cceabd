// This turns a path into the file's bytes: see file_io.h.
#include "transpiler/source/file_io.h"

#include <fstream>
#include <sstream>

namespace stereoshift {

bool readFile(const std::string& path, std::string* contents) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream text;
  text << in.rdbuf();
  *contents = text.str();
  return true;
}

}  // namespace stereoshift
