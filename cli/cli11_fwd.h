// CLI11 is declared, not included: it is the heaviest header of the tool (every translation unit that
// included it paid for its parser again), and only the files that register or parse options need it.
#pragma once

namespace CLI {
class App;
class ParseError;
}  // namespace CLI
