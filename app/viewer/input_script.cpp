#include "app/viewer/input_script.h"

#include "app/cli_options.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/view_state.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace kappa::viewer {

namespace {

class LineParser {
public:
    LineParser(const std::string& file, int line, std::vector<std::string> words)
        : file_(file), line_(line), words_(std::move(words)) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw std::runtime_error(file_ + ":" + std::to_string(line_) + ": " + problem);
    }
    size_t size() const { return words_.size(); }
    const std::string& word(size_t i) const { return words_[i]; }
    void expect_count(size_t lo, size_t hi, const char* usage) const {
        if (words_.size() < lo || words_.size() > hi) fail(std::string("expected '") + usage + "'");
    }
    float number(size_t i) const {
        auto x = cli::parse_number(words_[i]);
        if (!x) fail("'" + words_[i] + "' is not a number");
        return float(*x);
    }
    int positive_int(size_t i) const {
        auto n = cli::parse_int(words_[i]);
        if (!n || *n < 1) fail("'" + words_[i] + "' is not a positive integer");
        return *n;
    }

private:
    std::string file_;
    int line_;
    std::vector<std::string> words_;
};

ScriptStep parse_step(const LineParser& p, int line) {
    ScriptStep s;
    s.line = line;
    const std::string& cmd = p.word(0);
    if (cmd == "frames") {
        p.expect_count(2, 2, "frames N");
        s.kind = ScriptStep::Frames;
        s.count = p.positive_int(1);
    } else if (cmd == "drag") {
        p.expect_count(5, 7, "drag X0 Y0 X1 Y1 [left|right|middle] [STEPS]");
        s.kind = ScriptStep::Drag;
        s.from = {p.number(1), p.number(2)};
        s.to = {p.number(3), p.number(4)};
        s.count = 8;
        for (size_t i = 5; i < p.size(); ++i) {
            const std::string& w = p.word(i);
            if (w == "left") s.button = 0;
            else if (w == "right") s.button = 1;
            else if (w == "middle") s.button = 2;
            else s.count = p.positive_int(i);
        }
    } else if (cmd == "scroll") {
        p.expect_count(4, 4, "scroll X Y CLICKS");
        s.kind = ScriptStep::Scroll;
        s.from = {p.number(1), p.number(2)};
        s.amount = p.number(3);
    } else if (cmd == "key") {
        p.expect_count(2, 2, "key NAME");
        s.kind = ScriptStep::Key;
        s.name = p.word(1);
        if (!find_shortcut(s.name)) p.fail("unknown key '" + s.name + "' (see the help window, F1)");
    } else if (cmd == "set") {
        p.expect_count(3, 3, "set NAME VALUE");
        s.kind = ScriptStep::Set;
        s.name = p.word(1);
        s.value = p.word(2);
        ViewState probe;  // validate now rather than halfway through the run
        if (auto error = assign_setting(probe, s.name, s.value)) p.fail(*error);
    } else if (cmd == "panel") {
        p.expect_count(2, 2, "panel on|off");
        s.kind = ScriptStep::Panel;
        if (p.word(1) != "on" && p.word(1) != "off") p.fail("expected 'panel on' or 'panel off'");
        s.flag = p.word(1) == "on";
    } else if (cmd == "wait-compute") {
        p.expect_count(1, 1, "wait-compute");
        s.kind = ScriptStep::WaitCompute;
    } else if (cmd == "wait-hatching") {
        p.expect_count(1, 1, "wait-hatching");
        s.kind = ScriptStep::WaitHatching;
    } else if (cmd == "screenshot") {
        p.expect_count(2, 3, "screenshot PATH [panel|no-panel]");
        s.kind = ScriptStep::Screenshot;
        s.value = p.word(1);
        if (p.size() == 3) {
            if (p.word(2) != "panel" && p.word(2) != "no-panel") p.fail("expected 'panel' or 'no-panel'");
            s.flag = p.word(2) == "panel";
        }
    } else if (cmd == "save-view" || cmd == "load-view" || cmd == "open") {
        p.expect_count(2, 2, (cmd + " PATH").c_str());
        s.kind = cmd == "open" ? ScriptStep::Open : cmd == "save-view" ? ScriptStep::SaveView : ScriptStep::LoadView;
        s.value = p.word(1);
    } else {
        p.fail("unknown step '" + cmd +
               "' (steps: frames, drag, scroll, key, set, panel, wait-compute, wait-hatching, screenshot, save-view, "
               "load-view, open)");
    }
    return s;
}

}  // namespace

std::vector<ScriptStep> parse_script(const std::string& text, const std::string& file_name) {
    std::vector<ScriptStep> steps;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words_in(line);
        std::vector<std::string> words;
        for (std::string w; words_in >> w;) words.push_back(w);
        if (words.empty()) continue;
        steps.push_back(parse_step(LineParser(file_name, number, std::move(words)), number));
    }
    return steps;
}

std::vector<ScriptStep> read_script(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open the script");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_script(text.str(), path);
}

}  // namespace kappa::viewer
