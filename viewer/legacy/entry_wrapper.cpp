#include "legacy/entry_wrapper.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

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
    std::vector<bool> bound;  // per parameter: takes a compile argument
    size_t uniforms = 0;
    for (const auto& p : function.parameters) {
        bound.push_back(p.uniform);
        uniforms += p.uniform ? 1 : 0;
    }
    // The DirectX effect compiler also binds arguments to parameters that have no semantic and are
    // no output (NVIDIA's Quad.fxh relies on it): after the uniform ones, in order.
    for (size_t i = 0; i < function.parameters.size() && uniforms < statement.arguments.size(); ++i) {
        const auto& p = function.parameters[i];
        if (!bound[i] && !p.output && p.semantic.empty() && (castable(p.type) || p.type.rfind("sampler", 0) == 0)) {
            bound[i] = true;
            ++uniforms;
        }
    }
    if (uniforms != statement.arguments.size()) {
        error = function.name + " has " + std::to_string(uniforms) + " uniform parameter(s) but the compile statement passes " +
                std::to_string(statement.arguments.size()) + " argument(s)";
        return {};
    }
    std::string declarations, arguments;
    size_t next_argument = 0;
    const auto declare = [&](const std::string& declaration) { declarations += (declarations.empty() ? "" : ", ") + declaration; };
    for (size_t i = 0; i < function.parameters.size(); ++i) {
        const auto& p = function.parameters[i];
        if (!arguments.empty()) arguments += ", ";
        if (bound[i]) {
            const std::string& value = statement.arguments[next_argument++];
            arguments += castable(p.type) ? "(" + p.type + ")(" + value + ")" : "(" + value + ")";
            continue;
        }
        std::string semantic = p.semantic;
        for (char& c : semantic) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (semantic == "VFACE") {  // ps_3_0's facing register: positive for front faces
            declare("bool fxview_front_face : SV_IsFrontFace");
            arguments += "(" + p.type + ")(fxview_front_face ? 1.0 : -1.0)";
        } else if (semantic == "VPOS") {  // ps_3_0's pixel position
            declare("float4 fxview_frag_coord : SV_Position");
            arguments += "(" + p.type + ")(fxview_frag_coord)";
        } else {
            declare(p.declaration);
            arguments += p.name;
        }
    }
    const bool returns = function.return_type != "void";
    return function.return_type + " " + entry_name + "(" + declarations + ") " + function.return_semantic + " { " +
           (returns ? "return " : "") + function.name + "(" + arguments + "); }\n";
}

}  // namespace fxview::legacy
