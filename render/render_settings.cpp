#include "render/render_settings.h"

#include "geometry/mesh/creases.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdlib>

namespace kappa::render {

namespace {

template <typename E>
std::optional<E> lookup(const std::vector<std::string>& names, const std::string& s) {
    auto it = std::find(names.begin(), names.end(), s);
    if (it == names.end()) return std::nullopt;
    return E(it - names.begin());
}

}  // namespace

// Word order matches the enum order.
glm::vec3 unit_light_direction(const RenderSettings& settings) {
    const float len = glm::length(settings.light_dir);
    return len > 0 ? settings.light_dir / len : glm::vec3(0, 0, 1);
}

const std::vector<std::string>& shading_names() {
    static const std::vector<std::string> n{"none", "lambert", "toon", "hemisphere", "toon-bw", "gooch"};
    return n;
}
const std::vector<std::string>& colormap_names() {
    static const std::vector<std::string> n{"none", "k1", "k2", "mean", "gaussian", "principal", "dcurv"};
    return n;
}
const std::vector<std::string>& hatching_names() {
    static const std::vector<std::string> n{"none", "min", "max", "cross"};
    return n;
}
const std::vector<std::string>& hatch_style_names() {
    static const std::vector<std::string> n{"streamlines", "shader"};
    return n;
}
const std::vector<LineKind>& line_kinds() {
    using L = LineSelection;
    static const std::vector<LineKind> k{
        {"contours", &L::contours},
        {"suggestive", &L::suggestive},
        {"boundaries", &L::boundaries},
        {"creases", &L::creases},
        {"ridges", &L::ridges},
        {"valleys", &L::valleys},
        {"parabolic", &L::parabolic},
        {"mean-zero", &L::mean_zero},
        {"isophotes", &L::isophotes},
        {"topo", &L::topo},
        {"silhouette", &L::silhouette},
        {"apparent-ridges", &L::apparent_ridges},
        {"suggestive-highlights", &L::suggestive_highlights},
        {"principal-highlights", &L::principal_highlights},
        {"dwkr", &L::dwkr},
    };
    return k;
}

const LineKind* find_line_kind(const std::string& name) {
    for (const LineKind& k : line_kinds())
        if (k.name == name) return &k;
    return nullptr;
}

const std::vector<std::string>& line_names() {
    static const std::vector<std::string> n = [] {
        std::vector<std::string> names;
        for (const LineKind& k : line_kinds()) names.push_back(k.name);
        names.push_back("none");
        return names;
    }();
    return n;
}

std::optional<Shading> parse_shading(const std::string& s) { return lookup<Shading>(shading_names(), s); }
std::optional<ColorMap> parse_colormap(const std::string& s) { return lookup<ColorMap>(colormap_names(), s); }
std::optional<Hatching> parse_hatching(const std::string& s) { return lookup<Hatching>(hatching_names(), s); }
std::optional<HatchStyle> parse_hatch_style(const std::string& s) { return lookup<HatchStyle>(hatch_style_names(), s); }

std::optional<LineSelection> parse_lines(const std::string& list) {
    LineSelection l{false, false, false, false, false, false, false, false, false, false, false};
    std::vector<std::string> seen;
    size_t start = 0;
    for (;;) {
        const size_t comma = list.find(',', start);
        const std::string word = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (std::find(seen.begin(), seen.end(), word) != seen.end()) return std::nullopt;
        seen.push_back(word);
        if (const LineKind* k = find_line_kind(word)) l.*(k->flag) = true;
        else if (word != "none") return std::nullopt;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    // "none" together with a line kind is contradictory.
    if (std::find(seen.begin(), seen.end(), "none") != seen.end() && seen.size() > 1) return std::nullopt;
    return l;
}

std::optional<float> parse_detail(const std::string& s) {
    if (s == "off") return 0.0f;
    char* end = nullptr;
    const float x = std::strtof(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !(x > 0 && x <= 1000)) return std::nullopt;
    return x;
}

const std::vector<std::string>& vector_names() {
    static const std::vector<std::string> n{"normal", "principal1", "principal2", "asymptotic", "view"};
    return n;
}

std::optional<int> parse_vectors(const std::string& list) {
    if (list == "none") return 0;
    int bits = 0;
    size_t start = 0;
    for (;;) {
        const size_t comma = list.find(',', start);
        const std::string word = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto it = std::find(vector_names().begin(), vector_names().end(), word);
        if (it == vector_names().end()) return std::nullopt;
        const int bit = 1 << int(it - vector_names().begin());
        if (bits & bit) return std::nullopt;  // repeated
        bits |= bit;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return bits;
}

std::optional<float> parse_crease_angle(const std::string& s) {
    if (s == "auto") return -1.0f;
    if (s == "off") return 0.0f;
    char* end = nullptr;
    const float x = std::strtof(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !(x >= 0 && x < 180)) return std::nullopt;
    return x;
}

float resolved_crease_angle(float setting, const Mesh& mesh) {
    return setting < 0 ? auto_crease_angle(mesh) : setting;
}

std::optional<glm::vec4> parse_background(const std::string& s) {
    if (s == "white") return glm::vec4(1, 1, 1, 1);
    if (s == "black") return glm::vec4(0, 0, 0, 1);
    if (s == "transparent") return glm::vec4(1, 1, 1, 0);
    if (s.size() != 7 || s[0] != '#') return std::nullopt;
    glm::vec4 c(0, 0, 0, 1);
    for (int i = 0; i < 3; ++i) {
        int v = 0;
        for (int k = 0; k < 2; ++k) {
            const char ch = char(std::tolower(static_cast<unsigned char>(s[size_t(1 + 2 * i + k)])));
            const int d = (ch >= '0' && ch <= '9') ? ch - '0' : (ch >= 'a' && ch <= 'f') ? ch - 'a' + 10 : -1;
            if (d < 0) return std::nullopt;
            v = v * 16 + d;
        }
        c[i] = float(v) / 255.0f;
    }
    return c;
}

std::optional<glm::vec3> parse_color(const std::string& s) {
    if (s == "transparent") return std::nullopt;
    const auto c = parse_background(s);
    if (!c) return std::nullopt;
    return glm::vec3(*c);
}

std::string to_string(Shading s) { return shading_names()[size_t(s)]; }
std::string to_string(ColorMap m) { return colormap_names()[size_t(m)]; }
std::string to_string(Hatching h) { return hatching_names()[size_t(h)]; }
std::string to_string(HatchStyle h) { return hatch_style_names()[size_t(h)]; }
std::string to_string(const LineSelection& l) {
    std::string s;
    for (const LineKind& k : line_kinds())
        if (l.*(k.flag)) s += (s.empty() ? "" : ",") + k.name;
    return s.empty() ? "none" : s;
}

}  // namespace kappa::render
