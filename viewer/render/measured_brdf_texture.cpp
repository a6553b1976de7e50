#include "render/measured_brdf_texture.hpp"

#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/text.hpp"
#include "fit/measurement.hpp"

namespace fxview::render {

bool is_measured_brdf_file(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension == ".binary") return true;
    if (extension != ".csv") return false;
    // The header is among the first lines: only the first 4 KiB are read.
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<size_t>(in.gcount()));
    std::istringstream lines(head);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty() && line[0] != '#') return line.rfind("theta_in_deg,theta_out_deg,phi_out_deg", 0) == 0;
    return false;
}

texture::TextureData load_measured_brdf_texture(const std::string& path, const ResourceLimits& limits) {
    const fit::BrdfGrid grid = fit::read_measurement(path, limits);
    if (!fit::is_uniform_full_grid(grid))
        throw Error(path + ": a BRDF texture needs a uniform grid over theta 0..90 and phi 0..180 degrees");
    texture::Level level;
    level.width = static_cast<int>(grid.phi_out.size());
    level.height = static_cast<int>(grid.theta_out.size());
    level.depth = static_cast<int>(grid.theta_in.size());
    level.bytes.resize(static_cast<size_t>(level.width) * level.height * level.depth * 4 * sizeof(float));
    float* out = reinterpret_cast<float*>(level.bytes.data());
    for (size_t i = 0; i < grid.theta_in.size(); ++i)
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                // Data rows run top to bottom and are flipped on upload: GL row o is data row height - 1 - o.
                const size_t row = grid.theta_out.size() - 1 - o;
                float* texel = out + ((i * grid.theta_out.size() + row) * grid.phi_out.size() + p) * 4;
                const auto& v = grid.values[grid.index(i, o, p)];
                texel[0] = static_cast<float>(v[0]);
                texel[1] = static_cast<float>(v[1]);
                texel[2] = static_cast<float>(v[2]);
                texel[3] = 1.0f;
            }
    texture::TextureData data;
    data.type = texture::TextureType::Tex3D;
    data.format = texture::PixelFormat::RGBA32F;
    data.source = path;
    data.faces = {{std::move(level)}};
    return data;
}

}  // namespace fxview::render
