// The template part of cube_map.hpp: a radiance function tabulated on a cube, faces in parallel.
#pragma once
#include <thread>
#include <vector>

namespace fxview::lighting {

template <typename Radiance>
FloatCube tabulate(int size, int supersample, const Radiance& radiance) {
    FloatCube cube(size);
    std::vector<std::jthread> workers;
    for (int face = 0; face < 6; ++face)
        workers.emplace_back([&, face] {
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    glm::dvec3 sum(0.0);
                    for (int b = 0; b < supersample; ++b)
                        for (int a = 0; a < supersample; ++a) {
                            const double s = (x + (a + 0.5) / supersample) / size, t = (y + (b + 0.5) / supersample) / size;
                            sum += glm::dvec3(radiance(glm::normalize(cube_direction(face, s, t))));
                        }
                    cube.at(face, x, y) = glm::vec3(sum / double(supersample * supersample));
                }
        });
    return cube;
}

}  // namespace fxview::lighting
