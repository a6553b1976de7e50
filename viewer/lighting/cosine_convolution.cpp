#include "lighting/cosine_convolution.hpp"

#include <algorithm>
#include <numbers>

#include "lighting/cube_map_tabulate.hpp"

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
    // At each output texel's centre (tabulate without supersampling), faces in parallel.
    return tabulate(size, 1, [&](const glm::dvec3& direction) {
        const glm::vec3 n(direction);
        glm::dvec3 sum(0.0);
        for (const Texel& t : texels) sum += glm::dvec3(t.power) * static_cast<double>(std::max(glm::dot(n, t.direction), 0.0f));
        return glm::vec3(sum);
    });
}

}  // namespace fxview::lighting
