#include "app/value_parsing.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace fxview::app {
namespace {

template <typename Number>
bool parse_number(std::string_view text, Number& value) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    if (text.empty()) return false;
    if (text.front() == '+') text.remove_prefix(1);
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == separator) {
            parts.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    return parts;
}

glm::ivec2 parse_int_pair(const std::string& option, const std::string& text, char separator, int low, int high,
                          const char* shape) {
    const auto parts = split(text, separator);
    glm::ivec2 value;
    if (parts.size() != 2 || !parse_number(parts[0], value.x) || !parse_number(parts[1], value.y))
        throw UsageError(option + ": expected " + shape + ", got '" + text + "'");
    if (value.x < low || value.y < low || value.x > high || value.y > high)
        throw UsageError(option + ": each value must lie in " + std::to_string(low) + ".." + std::to_string(high) +
                         ", got '" + text + "'");
    return value;
}

}  // namespace

namespace {

template <typename Number>
std::vector<Number> parse_numbers(const std::string& option, const std::string& text, size_t count) {
    const auto parts = split(text, ',');
    std::vector<Number> values(parts.size());
    bool ok = parts.size() == count;
    for (size_t i = 0; ok && i < parts.size(); ++i) ok = parse_number(parts[i], values[i]) && std::isfinite(values[i]);
    if (!ok)
        throw UsageError(option + ": expected " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
    return values;
}

}  // namespace

std::vector<float> parse_floats(const std::string& option, const std::string& text, size_t count) {
    return parse_numbers<float>(option, text, count);
}

std::vector<double> parse_doubles(const std::string& option, const std::string& text, size_t count) {
    return parse_numbers<double>(option, text, count);
}

glm::vec2 parse_vec2(const std::string& option, const std::string& text) {
    const auto v = parse_floats(option, text, 2);
    return {v[0], v[1]};
}

glm::vec3 parse_vec3(const std::string& option, const std::string& text) {
    const auto v = parse_floats(option, text, 3);
    return {v[0], v[1], v[2]};
}

glm::vec4 parse_vec4(const std::string& option, const std::string& text) {
    const auto v = parse_floats(option, text, 4);
    return {v[0], v[1], v[2], v[3]};
}

glm::ivec2 parse_size(const std::string& option, const std::string& text) {
    return parse_int_pair(option, text, 'x', 1, 16384, "WIDTHxHEIGHT such as 256x256");
}

glm::ivec2 parse_pixel(const std::string& option, const std::string& text) {
    return parse_int_pair(option, text, ',', 0, 16383, "X,Y such as 32,32");
}

CLI::Validator finite_range(double low, double high) {
    return CLI::Validator(
        [low, high](std::string& input) -> std::string {
            double value = 0;
            const auto [end, error] = std::from_chars(input.data(), input.data() + input.size(), value);
            if (error != std::errc() || end != input.data() + input.size() || !std::isfinite(value) || value < low || value > high) {
                char text[96];
                std::snprintf(text, sizeof text, "a finite number in [%g, %g] is expected", low, high);
                return text;
            }
            return {};
        },
        "FLOAT in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
}

}  // namespace fxview::app
