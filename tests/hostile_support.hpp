// What the hostile-input tests share: a fresh folder per case, files written as given, a minimal
// native effect to wrap hostile declarations in.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>

#include "test_support.hpp"

namespace fxview::test {

inline const std::string kShaders = R"(GLSLShader VS { in vec3 position; void main() { gl_Position = vec4(position, 1.0); } }
GLSLShader FS { out vec4 color; void main() { color = vec4(1.0); } }
)";
inline const std::string kTechnique = "technique T { pass P { VertexShader = VS; FragmentShader = FS; } }\n";

// A fresh folder per case, so that the file-access policy sees only what the case puts there.
inline std::string folder(const std::string& name) {
    const std::string path = temp_path("hostile/" + name);
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path;
}

inline std::string write(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

inline bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace fxview::test
