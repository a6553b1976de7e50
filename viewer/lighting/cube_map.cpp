#include "lighting/cube_map.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::lighting {

FloatCube::FloatCube(int size_) : size(size_) {
    for (auto& face : faces) face.assign(static_cast<size_t>(size) * size, glm::vec3(0.0f));
}

glm::dvec3 cube_direction(int face, double s, double t) {
    const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
    switch (face) {
        case 0: return {1.0, -tc, -sc};
        case 1: return {-1.0, -tc, sc};
        case 2: return {sc, 1.0, tc};
        case 3: return {sc, -1.0, -tc};
        case 4: return {sc, -tc, 1.0};
        default: return {-sc, -tc, -1.0};
    }
}

glm::dvec3 texel_direction(int face, int x, int y, int size) {
    return glm::normalize(cube_direction(face, (x + 0.5) / size, (y + 0.5) / size));
}

namespace {
// The solid angle of the face region from (0, 0) to (u, v) in face coordinates [-1, 1] (Manne's formula).
double area_element(double u, double v) { return std::atan2(u * v, std::sqrt(u * u + v * v + 1.0)); }

}  // namespace

CubeFace select_cube_face(const glm::dvec3& r) {
    const glm::dvec3 a = glm::abs(r);
    double sc, tc, ma;
    int face;
    if (a.x >= a.y && a.x >= a.z) {
        face = r.x > 0 ? 0 : 1;
        sc = r.x > 0 ? -r.z : r.z;
        tc = -r.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        face = r.y > 0 ? 2 : 3;
        sc = r.x;
        tc = r.y > 0 ? r.z : -r.z;
        ma = a.y;
    } else {
        face = r.z > 0 ? 4 : 5;
        sc = r.z > 0 ? r.x : -r.x;
        tc = -r.y;
        ma = a.z;
    }
    return {face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)};
}

double texel_solid_angle(int x, int y, int size) {
    const double u0 = 2.0 * x / size - 1.0, u1 = 2.0 * (x + 1) / size - 1.0;
    const double v0 = 2.0 * y / size - 1.0, v1 = 2.0 * (y + 1) / size - 1.0;
    return area_element(u0, v0) - area_element(u0, v1) - area_element(u1, v0) + area_element(u1, v1);
}

glm::vec3 sample_bilinear(const FloatCube& cube, const glm::dvec3& direction) {
    const CubeFace f = select_cube_face(direction);
    const double x = f.s * cube.size - 0.5, y = f.t * cube.size - 0.5;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float ax = static_cast<float>(x - x0), ay = static_cast<float>(y - y0);
    const auto at = [&](int i, int j) { return cube.at(f.face, std::clamp(i, 0, cube.size - 1), std::clamp(j, 0, cube.size - 1)); };
    return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), ax), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), ax), ay);
}

FloatCube downsample(const FloatCube& cube) {
    FloatCube half(std::max(1, cube.size / 2));
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < half.size; ++y)
            for (int x = 0; x < half.size; ++x)
                half.at(face, x, y) = 0.25f * (cube.at(face, 2 * x, 2 * y) + cube.at(face, 2 * x + 1, 2 * y) + cube.at(face, 2 * x, 2 * y + 1) +
                                               cube.at(face, 2 * x + 1, 2 * y + 1));
    return half;
}

}  // namespace fxview::lighting
