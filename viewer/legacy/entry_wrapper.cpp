#include "legacy/entry_wrapper.hpp"

#include <algorithm>
#include <cctype>

namespace fxview::legacy {
namespace {

// Scalar, vector and matrix types take a C-style cast; structs and samplers are passed as they are.
bool castable(const std::string& type) {
    for (const char* base : {"float", "half", "double", "int", "uint", "bool", "fixed", "dword"})
        if (type.rfind(base, 0) == 0) {
            const std::string rest = type.substr(std::string(base).size());
            return std::all_of(rest.begin(), rest.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == 'x'; });
        }
    return false;
}

}  // namespace

std::string entry_wrapper(const FunctionSignature& function, const CompileStatement& statement, const std::string& entry_name,
                          std::string& error) {
    const auto uniforms = static_cast<size_t>(
        std::count_if(function.parameters.begin(), function.parameters.end(), [](const auto& p) { return p.uniform; }));
    if (uniforms != statement.arguments.size()) {
        error = function.name + " has " + std::to_string(uniforms) + " uniform parameter(s) but the compile statement passes " +
                std::to_string(statement.arguments.size()) + " argument(s)";
        return {};
    }
    std::string declarations, arguments;
    size_t next_argument = 0;
    for (const auto& p : function.parameters) {
        if (!arguments.empty()) arguments += ", ";
        if (p.uniform) {
            const std::string& value = statement.arguments[next_argument++];
            arguments += castable(p.type) ? "(" + p.type + ")(" + value + ")" : "(" + value + ")";
            continue;
        }
        declarations += (declarations.empty() ? "" : ", ") + p.declaration;
        arguments += p.name;
    }
    const bool returns = function.return_type != "void";
    return function.return_type + " " + entry_name + "(" + declarations + ") " + function.return_semantic + " { " +
           (returns ? "return " : "") + function.name + "(" + arguments + "); }\n";
}

}  // namespace fxview::legacy
