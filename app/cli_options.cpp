#include "cli_options.h"

#include "geometry/io/float_chars.h"
#include "geometry/surface_analysis.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace kappa::cli {

// ---- value parsers ---------------------------------------------------------

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

std::optional<double> parse_number(std::string_view text) {
    // std::from_chars is locale-independent; it rejects a leading '+'.
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (text.empty() || text.front() == '-') return std::nullopt;
    }
    double v = 0;
    auto [end, ec] = io::float_from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<int> parse_int(std::string_view text) {
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (text.empty() || text.front() == '-') return std::nullopt;
    }
    int v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return v;
}

std::optional<glm::vec3> parse_vec3(std::string_view text) {
    auto parts = split(text, ',');
    if (parts.size() != 3) return std::nullopt;
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
        auto x = parse_number(trim(parts[i]));
        if (!x || std::abs(*x) > std::numeric_limits<float>::max()) return std::nullopt;
        v[i] = float(*x);
    }
    return v;
}

std::optional<glm::ivec2> parse_size(std::string_view text) {
    size_t x = text.find_first_of("xX");
    if (x == std::string_view::npos) return std::nullopt;
    auto w = parse_int(text.substr(0, x)), h = parse_int(text.substr(x + 1));
    if (!w || !h || *w <= 0 || *h <= 0) return std::nullopt;
    return glm::ivec2(*w, *h);
}

std::vector<std::string> split(std::string_view text, char sep) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (;;) {
        size_t pos = text.find(sep, start);
        parts.emplace_back(text.substr(start, pos == std::string_view::npos ? std::string_view::npos : pos - start));
        if (pos == std::string_view::npos) return parts;
        start = pos + 1;
    }
}

std::string join(const std::vector<std::string>& items, const std::string& sep) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i ? sep : "") + items[i];
    return out;
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    // Levenshtein distance, one row at a time.
    auto distance = [](const std::string& a, const std::string& b) {
        std::vector<size_t> row(b.size() + 1);
        for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (size_t i = 1; i <= a.size(); ++i) {
            size_t diag = row[0];
            row[0] = i;
            for (size_t j = 1; j <= b.size(); ++j) {
                size_t up = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
                diag = up;
            }
        }
        return row[b.size()];
    };
    std::string best;
    size_t best_d = 3;
    for (const auto& c : candidates) {
        size_t d = distance(word, c);
        if (d < best_d && 2 * d < word.size()) best = c, best_d = d;
    }
    return best;
}

int fail(const std::string& message) {
    std::cerr << "kappa: " << message << "\n";
    return 1;
}

// ---- Parser -----------------------------------------------------------------

Parser::Parser(std::string command, std::string usage, std::string description)
    : command_(std::move(command)), usage_(std::move(usage)), description_(std::move(description)) {}

Parser& Parser::option(const std::string& names, const std::string& metavar, const std::string& help, Setter set,
                       const std::string& expects) {
    Option o;
    o.names = split(names, ',');
    for (auto& n : o.names) n = std::string(trim(n));
    o.metavar = metavar;
    o.help = help;
    o.expects = expects.empty() ? metavar : expects;
    o.set = std::move(set);
    options_.push_back(std::move(o));
    return *this;
}

Parser& Parser::flag(const std::string& names, bool& target, const std::string& help) {
    option(names, "", help, nullptr);
    options_.back().flag = &target;
    return *this;
}

Parser& Parser::number(const std::string& names, float& out, const std::string& help, double min, double max,
                       const std::string& metavar) {
    std::string expects = "a number";
    if (std::isfinite(min) && std::isfinite(max))
        expects += " in [" + format_number(min) + ", " + format_number(max) + "]";
    else if (std::isfinite(min))
        expects += " >= " + format_number(min);
    else if (std::isfinite(max))
        expects += " <= " + format_number(max);
    return option(
        names, metavar, help,
        [&out, min, max](const std::string& value) {
            auto v = parse_number(value);
            if (!v || *v < min || *v > max) return false;
            out = float(*v);
            return true;
        },
        expects);
}

Parser& Parser::integer(const std::string& names, int& out, const std::string& help, int min, int max,
                        const std::string& metavar) {
    std::string expects = "an integer";
    const bool has_min = min != std::numeric_limits<int>::min(), has_max = max != std::numeric_limits<int>::max();
    if (has_min && has_max)
        expects += " in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
    else if (has_min)
        expects += " >= " + std::to_string(min);
    else if (has_max)
        expects += " <= " + std::to_string(max);
    return option(
        names, metavar, help,
        [&out, min, max](const std::string& value) {
            auto v = parse_int(value);
            if (!v || *v < min || *v > max) return false;
            out = *v;
            return true;
        },
        expects);
}

Parser& Parser::vec3(const std::string& names, glm::vec3& out, const std::string& help) {
    return option(names, "X,Y,Z", help, [&out](const std::string& value) {
        auto v = parse_vec3(value);
        if (v) out = *v;
        return bool(v);
    });
}

Parser& Parser::size(const std::string& names, glm::ivec2& out, const std::string& help) {
    return option(names, "WxH", help, [&out](const std::string& value) {
        auto v = parse_size(value);
        if (v) out = *v;
        return bool(v);
    });
}

Parser& Parser::text(const std::string& names, std::string& out, const std::string& help,
                     const std::string& metavar) {
    return option(names, metavar, help, [&out](const std::string& value) {
        out = value;
        return true;
    });
}

Parser& Parser::choice(const std::string& names, std::string& out, const std::vector<std::string>& choices,
                       const std::string& help) {
    return option(
        names, join(choices, "|"), help,
        [&out, choices](const std::string& value) {
            if (std::find(choices.begin(), choices.end(), value) == choices.end()) return false;
            out = value;
            return true;
        },
        "one of " + join(choices, ", "));
}

Parser& Parser::choice_list(const std::string& names, std::vector<std::string>& out,
                            const std::vector<std::string>& choices, const std::string& help) {
    return option(
        names, "LIST", help + " (comma list of: " + join(choices, ", ") + ")",
        [&out, choices](const std::string& value) {
            std::vector<std::string> words;
            for (auto& w : split(value, ',')) {
                if (std::find(choices.begin(), choices.end(), w) == choices.end()) return false;
                if (std::find(words.begin(), words.end(), w) != words.end()) return false;
                words.push_back(w);
            }
            out = std::move(words);
            return true;
        },
        "a comma list of " + join(choices, ", "));
}

Parser& Parser::threads() {
    return option(
        "--threads", "N", "worker threads for the computation (default, or 0: one per core)",
        [](const std::string& value) {
            auto v = parse_int(value);
            if (!v || *v < 0 || *v > 4096) return false;
            kappa::set_thread_count(unsigned(*v));
            return true;
        },
        "an integer in [0, 4096]");
}

Parser& Parser::smoothing(SmoothingOptions& out) {
    option(
        "--estimator", "NAME",
        "curvature estimator: " + join(estimator_names(), ", ") +
            " (default rusinkiewicz; docs/estimators-and-accuracy.md)",
        [&out](const std::string& value) {
            const auto e = parse_estimator(value);
            if (e) out.estimator = *e;
            return e.has_value();
        },
        "one of " + join(estimator_names(), ", "));
    return option(
               "--smooth", "auto|off",
               "auto: estimate the mesh's noise level and choose the smoothing widths from it (widths given "
               "below are kept); off: only the widths given below (default)",
               [&out](const std::string& value) {
                   if (value != "auto" && value != "off") return false;
                   out.automatic = value == "auto";
                   return true;
               },
               "auto or off")
        .number("--smooth-normals", out.normals,
                  "Gaussian smoothing width (sigma, model units) for normals before curvature (default 0: none)", 0)
        .number("--smooth-curvature", out.curvature,
                "Gaussian smoothing width for the curvature tensor (default 0: none)", 0)
        .number("--smooth-dcurv", out.dcurv, "Gaussian smoothing width for C (default 0: none)", 0);
}

Parser& Parser::positional(const std::string& name, std::string& out, const std::string& help, bool required) {
    positionals_.push_back({name, &out, help, required});
    return *this;
}

Parser& Parser::epilog(const std::string& text) {
    epilog_ = text;
    return *this;
}

Parser::Option* Parser::find(const std::string& name) {
    for (auto& o : options_)
        if (std::find(o.names.begin(), o.names.end(), name) != o.names.end()) return &o;
    return nullptr;
}

bool Parser::seen(const std::string& name) const {
    for (const auto& o : options_)
        if (std::find(o.names.begin(), o.names.end(), name) != o.names.end()) return o.seen;
    for (const auto& p : positionals_)
        if (p.name == name) return p.seen;
    return false;
}

UsageError Parser::error(const std::string& message) const {
    return UsageError("kappa " + command_ + ": " + message);
}

std::string Parser::hint() const { return " (see 'kappa " + command_ + " --help')"; }

std::optional<int> Parser::parse(int argc, char** argv) {
    try {
        return parse_or_throw(argc, argv) ? std::nullopt : std::optional<int>(0);
    } catch (const UsageError& e) {
        std::cerr << e.what() << "\n";
        return 2;
    }
}

bool Parser::parse_or_throw(int argc, char** argv) {
    size_t next_positional = 0;
    bool only_positionals = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool is_option = !only_positionals && arg.size() > 1 && arg[0] == '-';
        if (!is_option) {
            if (next_positional >= positionals_.size())
                throw error("unexpected argument '" + arg + "'" + hint());
            Positional& p = positionals_[next_positional++];
            *p.out = arg;
            p.seen = true;
            continue;
        }
        if (arg == "--") {
            only_positionals = true;
            continue;
        }
        if (arg == "-h" || arg == "--help") {
            std::cout << help();
            return false;
        }
        // "--name=value" carries its value inline; short options never do.
        const size_t eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
        const std::string name = arg.substr(0, eq);
        Option* o = find(name);
        if (!o) {
            std::vector<std::string> known{"--help"};
            for (const auto& opt : options_) known.insert(known.end(), opt.names.begin(), opt.names.end());
            std::string guess = closest_match(name, known);
            throw error("unknown option '" + name + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?") +
                        hint());
        }
        o->seen = true;
        if (o->flag) {
            if (eq != std::string::npos) throw error(name + " takes no value" + hint());
            *o->flag = true;
            continue;
        }
        std::string value;
        if (eq != std::string::npos) {
            value = arg.substr(eq + 1);
        } else if (i + 1 < argc) {
            value = argv[++i];  // taken even if it starts with '-': --eye 0,-2.6,1.85
        } else {
            throw error(name + " expects " + o->expects + ", got nothing");
        }
        if (!o->set(value)) throw error(name + " expects " + o->expects + ", got '" + value + "'");
    }
    for (const auto& p : positionals_)
        if (p.required && !p.seen) throw error("missing " + p.name + hint());
    return true;
}

std::string Parser::help() const {
    // Two columns: "  -o, --output FILE" then the help text.
    std::vector<std::pair<std::string, std::string>> args, opts;
    for (const auto& p : positionals_) args.emplace_back(p.name, p.help + (p.required ? "" : " (optional)"));
    for (const auto& o : options_) {
        std::string left = join(o.names, ", ");
        if (!o.metavar.empty()) left += " " + o.metavar;
        opts.emplace_back(left, o.help);
    }
    opts.emplace_back("-h, --help", "show this help and exit");

    size_t width = 0;
    for (const auto* list : {&args, &opts})
        for (const auto& row : *list) width = std::max(width, row.first.size());
    width = std::min<size_t>(width, 28);

    std::ostringstream out;
    auto print = [&](const char* title, const std::vector<std::pair<std::string, std::string>>& rows) {
        if (rows.empty()) return;
        out << "\n" << title << ":\n";
        for (const auto& [left, text] : rows) {
            out << "  " << left;
            if (left.size() > width)
                out << "\n  " << std::string(width, ' ');
            else
                out << std::string(width - left.size(), ' ');
            out << "  " << text << "\n";
        }
    };
    out << "Usage: kappa " << command_ << (usage_.empty() ? "" : " " + usage_) << "\n\n" << description_ << "\n";
    print("Arguments", args);
    print("Options", opts);
    if (!epilog_.empty()) out << "\n" << epilog_ << (epilog_.back() == '\n' ? "" : "\n");
    return out.str();
}

}  // namespace kappa::cli
