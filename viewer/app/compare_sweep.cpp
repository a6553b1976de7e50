#include "app/compare_sweep.hpp"

#include <cmath>
#include <random>
#include <sstream>

#include "effect/parameter_values.hpp"
#include "effect/parser.hpp"

namespace fxview::app {
namespace {

bool is_integer(const effect::Parameter& p) { return p.type == "int" || p.type == "bool" || p.type.find("ivec") == 0; }

// The values a parameter takes in a sweep; empty when it has no range to sweep.
std::vector<double> sweep_values(const effect::Parameter& p) {
    if (p.type == "bool") return {0.0, 1.0};
    if (!p.ui.items.empty() && p.type == "int") {
        std::vector<double> indices;
        for (size_t i = 0; i < p.ui.items.size() && i < 8; ++i) indices.push_back(static_cast<double>(i));
        return indices;
    }
    if (!p.ui.min || !p.ui.max) return {};
    const double middle = is_integer(p) ? std::round(0.5 * (*p.ui.min + *p.ui.max)) : 0.5 * (*p.ui.min + *p.ui.max);
    return {*p.ui.min, *p.ui.max, middle};
}

std::string text(double value) {
    std::ostringstream out;
    out.precision(9);
    out << value;
    return out.str();
}

// Assignments for every value that differs from the defaults, each component written out.
std::vector<std::string> differences(const effect::Effect& effect, const effect::ParameterValues& defaults,
                                     const effect::ParameterValues& values) {
    std::vector<std::string> sets;
    for (const auto& p : effect.parameters) {
        const auto found = values.numbers.find(p.name);
        if (found == values.numbers.end() || found->second == defaults.numbers.at(p.name)) continue;
        std::string joined;
        for (double v : found->second) joined += (joined.empty() ? "" : ",") + text(v);
        sets.push_back(p.name + "=" + joined);
    }
    return sets;
}

}  // namespace

std::vector<SweepCase> sweep_cases(const effect::Effect& effect, int random_cases, unsigned seed) {
    const effect::ParameterValues defaults = effect::default_values(effect);
    std::vector<const effect::Parameter*> swept;
    for (const auto& p : effect.parameters)
        if (p.semantic.empty() && !effect::is_sampler_type(p.type) && p.array_size == 0 && !sweep_values(p).empty() &&
            defaults.numbers.count(p.name))
            swept.push_back(&p);
    std::vector<SweepCase> cases{{"defaults", {}}};
    for (const effect::Parameter* p : swept) {
        const std::vector<double> values = sweep_values(*p);
        static const char* const names[] = {"min", "max", "mid"};
        for (size_t i = 0; i < values.size(); ++i) {
            effect::ParameterValues v = defaults;
            for (double& component : v.numbers[p->name]) component = values[i];
            effect::enforce_constraints(effect, v, p->name);
            const bool ranged = p->type != "bool" && p->ui.items.empty();
            cases.push_back({p->name + "=" + (ranged ? std::string(names[i]) : text(values[i])), differences(effect, defaults, v)});
        }
    }
    std::mt19937 random(seed);
    for (int c = 0; c < random_cases && !swept.empty(); ++c) {
        effect::ParameterValues v = defaults;
        for (const effect::Parameter* p : swept) {
            const std::vector<double> values = sweep_values(*p);
            double value;
            if (p->type == "bool" || !p->ui.items.empty()) {
                value = values[std::uniform_int_distribution<size_t>(0, values.size() - 1)(random)];
            } else {
                value = std::uniform_real_distribution<double>(*p->ui.min, *p->ui.max)(random);
                if (is_integer(*p)) value = std::round(value);
            }
            for (double& component : v.numbers[p->name]) component = value;
            effect::enforce_constraints(effect, v, p->name);
        }
        cases.push_back({"random " + std::to_string(c + 1), differences(effect, defaults, v)});
    }
    return cases;
}

}  // namespace fxview::app
