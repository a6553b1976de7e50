// Parsing the small value syntaxes of the command line: "1,0,0", "256x128", "10,20".
// Every failure is a UsageError that names the option and what was expected.
#pragma once
#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace fxview::app {

std::vector<float> parse_floats(const std::string& option, const std::string& text, size_t count);
std::vector<double> parse_doubles(const std::string& option, const std::string& text, size_t count);  // model parameters: exact
glm::vec2 parse_vec2(const std::string& option, const std::string& text);
glm::vec3 parse_vec3(const std::string& option, const std::string& text);
glm::vec4 parse_vec4(const std::string& option, const std::string& text);
glm::ivec2 parse_size(const std::string& option, const std::string& text);   // WxH, each 1..16384
glm::ivec2 parse_pixel(const std::string& option, const std::string& text);  // X,Y, each >= 0

// A CLI11 check for a floating-point option: a finite number in [low, high]. CLI::Range alone lets
// "nan" through (every comparison with NaN is false).
CLI::Validator finite_range(double low, double high);

}  // namespace fxview::app
