#include "effect/parameter_values.hpp"

#include "core/text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "effect/parser.hpp"

namespace fxview::effect {

ParameterValues default_values(const Effect& effect) {
    ParameterValues values;
    for (const auto& p : effect.parameters) {
        if (!p.semantic.empty() || is_sampler_type(p.type)) continue;
        const size_t count = static_cast<size_t>(component_count(p.type) * std::max(1, p.array_size));
        values.numbers[p.name] = p.default_value ? p.default_value->numbers : std::vector<double>(count, 0.0);
    }
    return values;
}

namespace {

bool is_integral_type(const std::string& type) {
    return type == "int" || type == "bool" || type == "uint" || type.rfind("ivec", 0) == 0 || type.rfind("bvec", 0) == 0 ||
           type.rfind("uvec", 0) == 0;
}
bool is_boolean_type(const std::string& type) { return type == "bool" || type.rfind("bvec", 0) == 0; }
bool is_unsigned_type(const std::string& type) { return type == "uint" || type.rfind("uvec", 0) == 0; }

std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

const Annotation* find_annotation(const Parameter& p, const char* name) {
    for (const auto& a : p.annotations)
        if (to_lower(a.name) == name && !a.value.is_string && a.value.numbers.size() == 1) return &a;
    return nullptr;
}

double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace

std::pair<std::optional<double>, std::optional<double>> hard_range(const Parameter& p) {
    const Annotation* low = find_annotation(p, "hardmin");
    const Annotation* high = find_annotation(p, "hardmax");
    if (low || high)
        return {low ? std::optional<double>(low->value.numbers[0]) : std::nullopt, high ? std::optional<double>(high->value.numbers[0]) : std::nullopt};
    return {p.ui.min, p.ui.max};
}

std::string value_problem(const Parameter& p, const std::vector<double>& value) {
    const size_t needed = static_cast<size_t>(component_count(p.type) * std::max(1, p.array_size));
    if (value.size() != needed)
        return p.type + " " + p.name + " takes " + std::to_string(needed) + " value(s), got " + std::to_string(value.size());
    const bool integral = is_integral_type(p.type), boolean = is_boolean_type(p.type);
    // A combo's list, unless it is a generated list that was not resolved here ("spectral:library").
    const bool indexed = integral && !boolean && component_count(p.type) == 1 && !p.ui.items.empty() &&
                         !(p.ui.items.size() == 1 && p.ui.items[0].find(':') != std::string::npos);
    const auto [low, high] = hard_range(p);
    const bool ranged = component_count(p.type) <= 4;  // matrices have no UI range
    for (const double v : value) {
        if (!std::isfinite(v)) return p.name + " must be a finite number";
        if (integral) {
            const double lowest = boolean || is_unsigned_type(p.type) ? 0.0 : -2147483648.0;
            const double highest = boolean ? 1.0 : is_unsigned_type(p.type) ? 4294967295.0 : 2147483647.0;
            if (v != std::floor(v) || v < lowest || v > highest)
                return p.type + " " + p.name + " takes " + (boolean ? "true, false, 0 or 1" : "whole numbers of a 32-bit int") + ", not " + number_text(v);
        }
        if (indexed && (v < 0 || v >= static_cast<double>(p.ui.items.size())))
            return p.name + " = " + number_text(v) + " is not an entry of its list (0.." + std::to_string(p.ui.items.size() - 1) + ": " +
                   excerpt(p.ui.items.front()) + ", ...)";
        if (ranged && ((low && v < *low) || (high && v > *high)))
            return p.name + " = " + number_text(v) + " lies outside its range " + (low ? number_text(*low) : "-inf") + ".." +
                   (high ? number_text(*high) : "inf");
        if (!integral && std::abs(v) > 3.4028234663852886e38) return p.name + " = " + number_text(v) + " does not fit a float";
    }
    return {};
}

void check_defaults(Effect& effect) {
    for (auto& p : effect.parameters) {
        const auto [low, high] = hard_range(p);
        if (low && high && *low > *high) throw EffectError(p.where, p.name + ": HardMin " + number_text(*low) + " exceeds HardMax " + number_text(*high));
        if (!p.semantic.empty() || is_sampler_type(p.type) || !p.default_value || p.default_value->is_string) continue;
        const std::vector<double>& value = p.default_value->numbers;
        if (effect.legacy && component_count(p.type) <= 4)
            for (const double v : value) {
                if (p.ui.min && v < *p.ui.min) p.ui.min = v;
                if (p.ui.max && v > *p.ui.max) p.ui.max = v;
            }
        if (const std::string problem = value_problem(p, value); !problem.empty()) throw EffectError(p.where, "default: " + problem);
    }
}

void set_value_from_text(const Effect& effect, ParameterValues& values, const std::string& assignment) {
    const size_t equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0)
        throw UsageError("--set needs NAME=VALUE, got '" + excerpt(assignment) + "'");
    const std::string name = assignment.substr(0, equals), text = assignment.substr(equals + 1);
    const Parameter* parameter = effect.find_parameter(name);
    if (!parameter) throw UsageError("--set: the effect has no parameter '" + excerpt(name) + "'");
    if (!parameter->semantic.empty())
        throw UsageError("--set: " + name + " is bound to the semantic " + parameter->semantic + " and set by fxview");
    if (is_sampler_type(parameter->type)) {
        if (text.empty()) throw UsageError("--set " + name + ": needs a texture file");
        values.textures[name] = text;
        return;
    }
    auto& target = values.numbers[name];
    std::vector<double> parsed;
    if (!text.empty() && text[0] == '#') {
        if (text.size() != 7 && text.size() != 9) throw UsageError("--set " + name + ": colour must be #rrggbb or #rrggbbaa");
        for (size_t i = 1; i < text.size(); i += 2) {
            unsigned byte = 0;
            const auto [end, error] = std::from_chars(text.data() + i, text.data() + i + 2, byte, 16);
            if (error != std::errc() || end != text.data() + i + 2) throw UsageError("--set " + name + ": bad hex colour '" + excerpt(text) + "'");
            parsed.push_back(i < 7 ? srgb_to_linear(byte / 255.0) : byte / 255.0);  // alpha stays linear
        }
        if (target.size() == 4 && parsed.size() == 3) parsed.push_back(1.0);
    } else if (const auto item = std::find(parameter->ui.items.begin(), parameter->ui.items.end(), text);
               item != parameter->ui.items.end() && component_count(parameter->type) == 1) {
        parsed.push_back(static_cast<double>(item - parameter->ui.items.begin()));  // a combo entry by name
    } else {
        size_t start = 0;
        for (size_t i = 0; i <= text.size(); ++i) {
            if (i < text.size() && text[i] != ',') continue;
            const std::string item = text.substr(start, i - start);
            start = i + 1;
            if (item == "true" || item == "false") {
                parsed.push_back(item == "true" ? 1.0 : 0.0);
                continue;
            }
            double value = 0.0;
            const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
            if (error != std::errc() || end != item.data() + item.size() || item.empty() || !std::isfinite(value))
                throw UsageError("--set " + name + ": '" + excerpt(item) + "' is not a finite number");
            parsed.push_back(value);
        }
    }
    if (parsed.size() != target.size())
        throw UsageError("--set " + name + ": " + parameter->type + " needs " + std::to_string(target.size()) +
                         " value(s), got " + std::to_string(parsed.size()));
    if (const std::string problem = value_problem(*parameter, parsed); !problem.empty()) throw UsageError("--set " + name + ": " + problem);
    target = parsed;
}

void check_constraints(const Effect& effect, const ParameterValues& values) {
    for (const auto& p : effect.parameters) {
        if (p.ui.at_least.empty()) continue;
        const double value = values.numbers.at(p.name)[0], floor = values.numbers.at(p.ui.at_least)[0];
        if (value < floor) {
            const auto text = [](double v) {
                std::string s = std::to_string(v);
                s.erase(s.find_last_not_of('0') + 1);
                if (!s.empty() && s.back() == '.') s.pop_back();
                return s;
            };
            throw UsageError(p.name + " = " + text(value) + " lies below " + p.ui.at_least + " = " + text(floor) + ": " + p.name +
                             " must be at least " + p.ui.at_least + " (an empty range)");
        }
    }
}

void enforce_constraints(const Effect& effect, ParameterValues& values, const std::string& changed) {
    for (const auto& p : effect.parameters) {
        if (p.ui.at_least.empty()) continue;
        double& value = values.numbers.at(p.name)[0];
        double& floor = values.numbers.at(p.ui.at_least)[0];
        if (value >= floor) continue;
        if (changed == p.ui.at_least) floor = value;  // the user moved the lower one up: it stops at the upper
        else value = floor;
    }
}

}  // namespace fxview::effect
