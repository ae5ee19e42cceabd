// The HLSL splice's edit buffer: collects text insertions and replacements by byte offset into the
// original source and applies them in one pass, so everything outside the edits stays byte for
// byte what it was. Also where a block of new declarations goes before or after a declaration
// (outside preprocessor conditionals, comments and directives, on lines of its own).
#pragma once

#include "transpiler/backend/hlsl_splice/token_view.h"

#include <string>
#include <utility>
#include <vector>

namespace stereoshift::hlsl_splice {

class EditBuffer {
 public:
  explicit EditBuffer(const std::string& source);

  // Replaces `remove` bytes at `offset` with `insert`. Edits at one offset apply in the order added.
  void add(size_t offset, size_t remove, std::string insert);
  // The source with every edit applied.
  std::string apply() const;
  // The file's line ending: "\r\n" when most of its lines end so, else "\n".
  const std::string& newline() const { return newline_; }

 private:
  struct Edit {
    size_t offset;
    size_t remove;
    std::string insert;
    size_t order;
  };
  const std::string& source_;
  std::vector<Edit> edits_;
  std::string newline_;
};

// Where to insert text that must come before the declaration starting at `offset`, not before
// `notBefore`. Returns the offset and whether it is at a line start.
std::pair<size_t, bool> insertionBefore(const TokenView& view, size_t offset, size_t notBefore);

// Insert `block` (lines ending in newlines) before the declaration at `offset`.
void insertBlockBefore(EditBuffer& edits, const TokenView& view, size_t offset, size_t notBefore,
                       const std::string& block);

// Insert `block` after the token `tok` (a closing brace), starting on a new line.
void insertBlockAfter(EditBuffer& edits, const TokenView& view, size_t tok, const std::string& block);

}  // namespace stereoshift::hlsl_splice
