#include "effect/parameter_values.hpp"

#include "core/text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

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

double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace

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
    // int, ivec and bool parameters take whole numbers a 32-bit int holds (bool: 0 or 1).
    const bool integral = parameter->type == "int" || parameter->type == "bool" || parameter->type.rfind("ivec", 0) == 0 ||
                          parameter->type.rfind("bvec", 0) == 0;
    const bool boolean = parameter->type == "bool" || parameter->type.rfind("bvec", 0) == 0;
    for (double v : parsed)
        if (integral && (v != std::floor(v) || v < (boolean ? 0.0 : -2147483648.0) || v > (boolean ? 1.0 : 2147483647.0)))
            throw UsageError("--set " + name + ": " + parameter->type + " takes " + (boolean ? "true, false, 0 or 1" : "whole numbers of a 32-bit int") +
                             ", not " + excerpt(text));
    if (parsed.size() != target.size())
        throw UsageError("--set " + name + ": " + parameter->type + " needs " + std::to_string(target.size()) +
                         " value(s), got " + std::to_string(parsed.size()));
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
