// `--diff`: this turns an input and its converted text into a unified diff (the format of
// `diff -u` / `git diff`, three lines of context), so the edits of a conversion can be reviewed and
// applied like a patch. Lines are compared whole, line ends included; a text that does not end in
// a line break gets diff's "\ No newline at end of file" marker.
#pragma once

#include <string>

namespace stereoshift {

// The unified diff from `before` (named `beforeName` in the --- header) to `after` (`afterName`);
// empty when the two texts are equal.
std::string unifiedDiff(const std::string& before, const std::string& after, const std::string& beforeName,
                        const std::string& afterName);

}  // namespace stereoshift
