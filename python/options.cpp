// Keyword arguments to command-line words and back to Python errors: the
// module takes exactly the command line's options (app/render_options.h).
#include "bindings.h"

#include "app/appearance_settings.h"

#include <regex>

namespace kappa::python {

namespace {

std::string keyword_to_option(std::string name) {
    for (char& c : name)
        if (c == '_') c = '-';
    return "--" + name;
}

// "kappa render: --line-width expects X, got 'a' (see ...)" -> "line_width expects X, got 'a'"
}  // namespace

std::string keyword_message(const std::string& usage_message) {
    std::string message = usage_message;
    message = std::regex_replace(message, std::regex("^kappa [a-z]+: "), "");
    message = std::regex_replace(message, std::regex(" ?\\(see 'kappa [a-z]+ --help'\\)"), "");
    std::string out;
    std::smatch match;
    const std::regex option("--([a-z][a-z0-9-]*)");
    while (std::regex_search(message, match, option)) {
        std::string name = match[1];
        for (char& c : name)
            if (c == '-') c = '_';
        out += match.prefix().str() + name;
        message = match.suffix();
    }
    return out + message;
}

namespace {

std::string value_text(const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "on" : "off";
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) || py::isinstance<py::array>(value)) {
        std::string out;
        for (const py::handle item : value) out += (out.empty() ? "" : ",") + value_text(item);
        return out;
    }
    return py::str(value);
}

}  // namespace

std::vector<std::string> option_words(const py::dict& kwargs) {
    std::vector<std::string> words;
    for (const auto& [key, value] : kwargs) {
        if (value.is_none()) continue;
        const std::string name = key.cast<std::string>();
        const std::string option = keyword_to_option(name);
        const app::AppearanceSetting* setting = app::find_appearance_setting(option.substr(2));
        if (setting && setting->flag && py::isinstance<py::bool_>(value)) {
            if (value.cast<bool>()) words.push_back(option);
            continue;
        }
        std::string text = value_text(value);
        if (name == "size" && !py::isinstance<py::str>(value)) {  // (w, h) -> WxH
            const auto comma = text.find(',');
            if (comma != std::string::npos) text[comma] = 'x';
        }
        words.push_back(option);
        words.push_back(text);
    }
    return words;
}

void parse_words(cli::Parser& parser, const std::vector<std::string>& words) {
    std::vector<std::string> args{parser.command()};
    args.insert(args.end(), words.begin(), words.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    for (const auto& w : words)
        if (w == "-h" || w == "--help") throw py::value_error("help is not a keyword argument");
    try {
        parser.parse_or_throw(int(args.size()), argv.data());
    } catch (const cli::UsageError& e) {
        const std::string message = keyword_message(e.what());
        if (message.rfind("unknown option", 0) == 0)
            throw py::type_error("unexpected keyword argument" + message.substr(std::string("unknown option").size()));
        throw py::value_error(message);
    }
}

}  // namespace kappa::python
