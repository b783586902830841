// Command-line parsing shared by every kappa subcommand.
//
// Syntax accepted (conventions.md, "Command line contract"):
//   --name VALUE  or  --name=VALUE   the value is the next argument even when
//                                    it starts with '-' (--eye 0,-2.6,1.85)
//   -o VALUE                         short aliases take the next argument
//   --flag                           options without a value
//   --                               everything after is positional
// Errors are one line on stderr, "kappa CMD: problem", exit status 2.
//
// Typical use inside a subcommand:
//   std::string mesh; glm::ivec2 size{1024, 768};
//   cli::Parser p("render", "[MESH] -o OUT.png [options]", "Render a mesh to a PNG.");
//   p.positional("MESH", mesh, "mesh file; default: the built-in model")
//    .size("--size", size, "image size in pixels (default 1024x768)")
//    .threads();
//   if (auto status = p.parse(argc, argv)) return *status;
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kappa {
struct SmoothingOptions;
}

namespace kappa::cli {

// ---- value parsers: std::nullopt when the text is not a valid value -------

// A finite decimal number ("2.5", "-1e-3", "+4"); the whole text must match.
std::optional<double> parse_number(std::string_view text);
// A decimal integer that fits in an int.
std::optional<int> parse_int(std::string_view text);
// Three numbers separated by commas: "X,Y,Z" (spaces around numbers allowed).
std::optional<glm::vec3> parse_vec3(std::string_view text);
// Two positive integers "WxH" (or "WXH").
std::optional<glm::ivec2> parse_size(std::string_view text);
// Splits at every `sep`; "a,,b" gives {"a", "", "b"}, "" gives {""}.
std::vector<std::string> split(std::string_view text, char sep);
// "a, b, c"
std::string join(const std::vector<std::string>& items, const std::string& sep);

// The candidate closest to `word` by edit distance if it is a plausible typo
// (distance <= 2 and less than half the word), else "".
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// A usage error; what() is the complete one-line message, e.g.
// "kappa render: --size expects WxH, got '12'". Exit status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Prints "kappa: MESSAGE" to stderr and returns 1: for runtime failures
// (unreadable mesh, unwritable output) after the arguments were accepted.
int fail(const std::string& message);

class Parser {
public:
    // `command` is the subcommand name ("render"), `usage` what follows
    // "kappa render" in the usage line, `description` one or more sentences.
    Parser(std::string command, std::string usage, std::string description);

    // Called with the option's value; returns false when the value is invalid
    // (the error then reads "--name expects EXPECTS, got 'VALUE'"). May also
    // throw UsageError (use error()) for a message of its own.
    using Setter = std::function<bool(const std::string& value)>;

    // `names`: "--size", or a short alias and the long name "-o,--output".
    // `metavar`: the value's placeholder in help ("WxH"); `expects`: how the
    // error describes a valid value (defaults to the metavar).
    Parser& option(const std::string& names, const std::string& metavar, const std::string& help,
                   Setter set, const std::string& expects = "");
    Parser& flag(const std::string& names, bool& target, const std::string& help);

    // Typed options. Bounds are inclusive.
    Parser& number(const std::string& names, float& out, const std::string& help,
                   double min = -std::numeric_limits<double>::infinity(),
                   double max = std::numeric_limits<double>::infinity(), const std::string& metavar = "X");
    Parser& integer(const std::string& names, int& out, const std::string& help,
                    int min = std::numeric_limits<int>::min(), int max = std::numeric_limits<int>::max(),
                    const std::string& metavar = "N");
    Parser& vec3(const std::string& names, glm::vec3& out, const std::string& help);
    Parser& size(const std::string& names, glm::ivec2& out, const std::string& help);
    Parser& text(const std::string& names, std::string& out, const std::string& help,
                 const std::string& metavar = "TEXT");
    // One word out of `choices`; help shows them as "a|b|c".
    Parser& choice(const std::string& names, std::string& out, const std::vector<std::string>& choices,
                   const std::string& help);
    // The same for an enum: choices are (word, value) pairs.
    template <typename E>
    Parser& choice(const std::string& names, E& out, const std::vector<std::pair<std::string, E>>& choices,
                   const std::string& help);
    // A comma list of words from `choices` ("contours,suggestive"), no repeats.
    Parser& choice_list(const std::string& names, std::vector<std::string>& out,
                        const std::vector<std::string>& choices, const std::string& help);
    // --threads N: worker threads for the computation (0 = all cores); calls
    // kappa::set_thread_count while parsing.
    Parser& threads();
    // --estimator NAME (SmoothingOptions::estimator), --smooth auto|off
    // (SmoothingOptions::automatic) and --smooth-normals,
    // --smooth-curvature, --smooth-dcurv: Gaussian widths (sigma, model
    // units) passed to the curvature engine; 0 = off, or chosen with auto.
    Parser& smoothing(SmoothingOptions& out);

    // Positional arguments are filled in the order they are declared.
    Parser& positional(const std::string& name, std::string& out, const std::string& help, bool required);

    // Extra text printed at the end of --help (examples, notes).
    Parser& epilog(const std::string& text);

    // Parses argv[1..argc) (argv[0] is the subcommand name). Returns
    // std::nullopt when the command should run; otherwise the status it must
    // return: 0 after printing --help, 2 after printing a usage error.
    std::optional<int> parse(int argc, char** argv);
    // The same, but throws UsageError; returns false after printing --help.
    bool parse_or_throw(int argc, char** argv);

    // Whether an option (any of its names) or positional appeared.
    bool seen(const std::string& name) const;

    // A UsageError "kappa CMD: MESSAGE" for checks made after parsing.
    UsageError error(const std::string& message) const;
    std::string help() const;
    const std::string& command() const { return command_; }

private:
    struct Option {
        std::vector<std::string> names;
        std::string metavar;  // empty: a flag
        std::string help;
        std::string expects;
        Setter set;
        bool* flag = nullptr;
        bool seen = false;
    };
    struct Positional {
        std::string name;
        std::string* out;
        std::string help;
        bool required;
        bool seen = false;
    };

    Option* find(const std::string& name);
    std::string hint() const;

    std::string command_, usage_, description_, epilog_;
    std::vector<Option> options_;
    std::vector<Positional> positionals_;
};

template <typename E>
Parser& Parser::choice(const std::string& names, E& out, const std::vector<std::pair<std::string, E>>& choices,
                       const std::string& help) {
    std::vector<std::string> words;
    for (const auto& c : choices) words.push_back(c.first);
    return option(
        names, join(words, "|"), help,
        [&out, choices](const std::string& value) {
            for (const auto& c : choices)
                if (c.first == value) {
                    out = c.second;
                    return true;
                }
            return false;
        },
        "one of " + join(words, ", "));
}

}  // namespace kappa::cli
