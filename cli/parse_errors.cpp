// The command line's usage errors (see parse_errors.h): the edit distance behind "did you mean",
// the nearest option, and CLI11's error kinds turned into the house's messages.
#include "cli/parse_errors.h"

#include "cli/conversion_options.h"
#include "cli/diagnostic_output.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace stereoshift {

size_t editDistance(const std::string& a, const std::string& b) {
  // Optimal string alignment: the Levenshtein table plus a swap of two neighbours ("sorce" is one
  // edit from "source", "souce" from "source", "suorce" one swap).
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

namespace {

// The command's apps: the top-level one and the subcommand being parsed (whose options count too).
std::vector<const CLI::App*> appsInUse(const CLI::App& app) {
  std::vector<const CLI::App*> apps{&app};
  for (const CLI::App* sub : app.get_subcommands()) apps.push_back(sub);
  return apps;
}

const CLI::Option* findOption(const std::vector<const CLI::App*>& apps, const std::string& name) {
  for (const CLI::App* a : apps)
    if (const CLI::Option* option = a->get_option_no_throw(name)) return option;
  return nullptr;
}

// "--eye-source" for an option that has a long name, "-D" for one that has only a short one.
std::string longestName(const CLI::Option& option) {
  if (!option.get_lnames().empty()) return "--" + option.get_lnames().front();
  if (!option.get_snames().empty()) return "-" + option.get_snames().front();
  return option.get_name();
}

// The known option nearest to `given` (an unknown "--name" or "--name=value"), when it is close
// enough to be a typo: at most a third of the name's letters wrong.
std::optional<std::string> nearestOption(const std::vector<const CLI::App*>& apps, std::string given) {
  given = given.substr(0, given.find('='));
  if (given.rfind("--", 0) != 0) return std::nullopt;
  std::string name = given.substr(2);
  std::optional<std::string> best;
  size_t bestDistance = std::max<size_t>(1, name.size() / 3) + 1;
  for (const CLI::App* a : apps)
    for (const CLI::Option* option : a->get_options())
      for (const auto& candidate : option->get_lnames()) {
        size_t distance = editDistance(name, candidate);
        if (distance < bestDistance) {
          bestDistance = distance;
          best = "--" + candidate;
        }
      }
  return best;
}

// CLI11's type names, in words.
std::string expectedValue(const CLI::Option& option) {
  std::string type = option.get_type_name();
  if (type == "UINT") return "a non-negative integer";
  if (type == "INT") return "an integer";
  if (type == "FLOAT") return "a number";
  return type.empty() ? "a value" : type;
}

std::vector<std::string> usageErrors(const CLI::App& app, const CLI::ParseError& error) {
  const std::vector<const CLI::App*> apps = appsInUse(app);
  const std::string what = error.what();
  std::vector<std::string> messages;
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    std::vector<std::string> extras;
    for (const CLI::App* a : apps)
      for (const auto& arg : a->remaining())
        if (std::find(extras.begin(), extras.end(), arg) == extras.end()) extras.push_back(arg);
    for (size_t i = 0; i < extras.size(); ++i) {
      const std::string& arg = extras[i];
      if (arg.size() < 2 || arg[0] != '-') {
        messages.push_back("unexpected argument '" + arg + "'");
        continue;
      }
      // "--job-timout 5": the word after an unknown option is taken to be its value, not another error.
      if (arg.find('=') == std::string::npos && i + 1 < extras.size() && extras[i + 1].rfind("-", 0) != 0) ++i;
      std::string message = "unknown option '" + arg + "'";
      std::string spelled = arg.substr(0, arg.find('='));
      // A subcommand's own options first: a name close to the conversion's is no help there.
      std::vector<const CLI::App*> own = apps.size() > 1 ? std::vector<const CLI::App*>{apps.back()} : apps;
      auto nearest = nearestOption(own, arg);
      if (auto anywhere = nearestOption(apps, arg); apps.size() > 1 && anywhere && *anywhere == spelled) {
        // The name is right, the place is not: an option of the conversion given to a subcommand
        // that does not read it (`verify --pipeline a.vert,a.frag`).
        const std::string sub = apps.back()->get_name();
        message = "option '" + spelled + "' is not one of " + sub + "'s (it belongs to the conversion: stereoshift " +
                  spelled + " ...)";
        if (sub == "verify" && spelled == "--pipeline")
          message += "; verify takes the stages of a pipeline as its inputs: stereoshift verify a.vert a.frag";
      } else if (nearest) {
        message += "; did you mean '" + *nearest + "'?";
      }
      messages.push_back(message);
    }
    if (!messages.empty()) return messages;
  }
  // "Could not convert: --binding = -1": a value of the wrong type.
  static const std::string couldNotConvert = "Could not convert: ";
  if (dynamic_cast<const CLI::ConversionError*>(&error) && what.rfind(couldNotConvert, 0) == 0) {
    std::string rest = what.substr(couldNotConvert.size());
    size_t equals = rest.find(" = ");
    if (equals != std::string::npos) {
      std::string name = rest.substr(0, equals), value = rest.substr(equals + 3);
      if (const CLI::Option* option = findOption(apps, name))
        return {longestName(*option) + ": invalid value '" + value + "' (expected " + expectedValue(*option) + ")"};
    }
  }
  // "--target: 1 required TEXT missing": an option given without its value.
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    std::string given = what.substr(0, what.find(':'));
    if (const CLI::Option* option = findOption(apps, given)) {
      std::string name = longestName(*option);
      bool enumerated = enumeratedOptions().count(name) > 0;
      return {name + " needs a value " + (enumerated ? validValues(name) : "(" + expectedValue(*option) + ")")};
    }
  }
  return {what};
}

}  // namespace

int reportParseError(const CLI::App& app, const CLI::ParseError& error, std::ostream& log) {
  // --help and --version arrive as "errors" with exit code 0: CLI11 prints those itself.
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);
  std::vector<std::string> messages = usageErrors(app, error);
  for (const auto& message : messages) log << "stereoshift: error: " << message << "\n";
  printErrorSummary(static_cast<int>(messages.size()));
  return 2;
}

}  // namespace stereoshift
