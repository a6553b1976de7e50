#include "lighting/cosine_convolution.hpp"

#include <algorithm>
#include <numbers>
#include <thread>

namespace fxview::lighting {

FloatCube cosine_convolved(const FloatCube& radiance, int size, int source_size) {
    FloatCube source = radiance;
    while (source.size > source_size) source = downsample(source);
    // Each source texel as a direction and its radiance times solid angle / π.
    struct Texel {
        glm::vec3 direction, power;
    };
    std::vector<Texel> texels;
    texels.reserve(static_cast<size_t>(6) * source.size * source.size);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < source.size; ++y)
            for (int x = 0; x < source.size; ++x) {
                const glm::vec3 value = source.at(face, x, y);
                if (value == glm::vec3(0.0f)) continue;
                texels.push_back({glm::vec3(texel_direction(face, x, y, source.size)),
                                  value * static_cast<float>(texel_solid_angle(x, y, source.size) / std::numbers::pi)});
            }
    FloatCube out(size);
    std::vector<std::jthread> workers;
    for (int face = 0; face < 6; ++face)
        workers.emplace_back([&, face] {
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const glm::vec3 n(texel_direction(face, x, y, size));
                    glm::dvec3 sum(0.0);
                    for (const Texel& t : texels) sum += glm::dvec3(t.power) * static_cast<double>(std::max(glm::dot(n, t.direction), 0.0f));
                    out.at(face, x, y) = glm::vec3(sum);
                }
        });
    workers.clear();
    return out;
}

}  // namespace fxview::lighting
