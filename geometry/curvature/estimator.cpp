#include "estimator.h"

namespace kappa {

const std::vector<std::string>& estimator_names() {
    static const std::vector<std::string> names = {"rusinkiewicz", "jet", "tensor-averaging", "normal-fit",
                                                   "points-normals-fit"};
    return names;
}

const std::string& estimator_name(Estimator e) { return estimator_names()[size_t(e)]; }

std::optional<Estimator> parse_estimator(const std::string& name) {
    const auto& names = estimator_names();
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return Estimator(i);
    return std::nullopt;
}

}  // namespace kappa
