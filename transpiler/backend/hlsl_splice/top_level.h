// The HLSL splice's top-level parser: turns the tokens of a file into its functions (attributes,
// return semantic, parameters with their stream element types), its structs (members and
// semantics) and every name declared at file scope. It reads declarations, not statements: the
// bodies of functions are only bracket ranges here.
#pragma once

#include "transpiler/backend/hlsl_splice/token_view.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stereoshift::hlsl_splice {

// Storage classes, interpolation modifiers and other words that are not part of a type name.
const std::set<std::string>& modifierWords();
bool isFloat4Like(const std::string& type);

struct Param {
  size_t begin = 0, end = 0;  // token range
  std::string name;
  size_t nameTok = npos;
  std::string typeName;  // last non-modifier identifier of the type (outside template arguments)
  bool isOut = false;    // `out` or `inout`
  std::string semantic;
  std::string streamElement;  // TriangleStream/LineStream/PointStream<T>: T
};

struct Attr {
  size_t open, close;  // token indices of '[' and ']'
};

struct Function {
  std::vector<Attr> attrs;
  size_t declBegin = 0;  // first token (attributes included)
  size_t typeBegin = 0;  // first token after the attributes
  size_t nameTok = 0;
  size_t paramOpen = 0, paramClose = 0;
  size_t semColon = npos, semTok = npos;  // `: SEMANTIC` after the parameter list
  size_t bodyOpen = 0, bodyClose = 0;
  std::vector<Param> params;
};

struct Member {
  std::string name;
  std::string typeName;
  std::string semantic;
};

struct StructDef {
  std::string name;
  size_t nameTok = 0;
  size_t endTok = 0;  // last token of the definition (normally ';')
  std::vector<Member> members;
};

// What a file declares at file scope.
struct TopLevel {
  std::vector<Function> functions;
  std::vector<StructDef> structs;
  std::map<std::string, size_t> names;  // file-scope name -> token

  const StructDef* findStruct(const std::string& name) const;
  // Member path (".a.b") of the SV_Position member of struct `name`, searching nested structs.
  std::optional<std::string> positionPath(const std::string& name, int depth = 0) const;
  // The function whose body holds token `tok`, or null.
  const Function* enclosingFunction(size_t tok) const;
};

std::optional<SpliceError> parseTopLevel(const TokenView& view, TopLevel& top);

// Whether one of `ours` (names the splice declares) collides with a file-scope name or a macro of
// the source (this also catches a second injection into an already injected shader), or whether
// register(b<cbufferRegister>) in space0 is taken.
// `checkRegister`: whether register(b<cbufferRegister>) must be free (not with 3Dmigoto's texture).
std::optional<SpliceError> checkConflicts(const TokenView& view, const TopLevel& top,
                                          const std::vector<std::string>& ours, uint32_t cbufferRegister,
                                          bool checkRegister = true);

}  // namespace stereoshift::hlsl_splice
