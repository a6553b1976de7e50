#include "reference/cpu_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "lighting/cube_map.hpp"
#include "image/color_encoding.hpp"

namespace fxview::reference {
namespace {

// GL's wrap of an integer texel coordinate (spec table 8.20).
int wrap(int i, int size, GLenum mode) {
    switch (mode) {
        case GL_REPEAT: return ((i % size) + size) % size;
        case GL_MIRRORED_REPEAT: {
            const int period = ((i % (2 * size)) + 2 * size) % (2 * size);
            return period >= size ? 2 * size - 1 - period : period;
        }
        default: return std::clamp(i, 0, size - 1);  // CLAMP_TO_EDGE
    }
}

glm::dvec4 texel(const texture::TextureData& t, bool srgb, int i, int j, int face = -1, int slice = 0) {
    float rgba[4];
    // GL row j counts from the bottom; 2D data (and each 3D slice) keep the image's top row first,
    // cube faces are stored in GL's order (row 0 is t = 0).
    if (face < 0) texture::read_texel(t, 0, 0, i, t.height() - 1 - j, rgba, slice);
    else texture::read_texel(t, face, 0, i, j, rgba);
    glm::dvec4 value(rgba[0], rgba[1], rgba[2], rgba[3]);
    if (srgb)
        for (int c = 0; c < 3; ++c) value[c] = image::srgb_decode(static_cast<float>(value[c]));
    return value;
}

// The direction through the centre of texel (i, j) of `face`. A coordinate one texel outside the face
// is put just across its edge instead, so that re-selecting the face lands on the neighbouring face's
// edge texel at the same place along the edge (a texel centre further out would be projected and
// shifted along the edge).
glm::dvec3 texel_direction(int face, int i, int j, int size) {
    const auto coordinate = [size](int k) {
        if (k < 0) return -1.0 - 1e-9;
        if (k >= size) return 1.0 + 1e-9;
        return 2.0 * (k + 0.5) / size - 1.0;
    };
    return lighting::cube_direction(face, 0.5 * (coordinate(i) + 1.0), 0.5 * (coordinate(j) + 1.0));
}

}  // namespace

CubeSample sample_cube(const texture::TextureData& t, const effect::SamplerState& s, bool srgb, glm::dvec3 direction) {
    if (s.min_filter != GL_NEAREST && s.min_filter != GL_LINEAR)
        throw Error("CPU sampler: mipmapped filtering depends on screen derivatives; use nearest or linear");
    if (s.min_filter != s.mag_filter) throw Error("CPU sampler: min and mag filters must agree");
    const int size = t.width();
    const lighting::CubeFace f = lighting::select_cube_face(direction);
    if (s.min_filter == GL_NEAREST) {
        const int i = std::clamp(static_cast<int>(std::floor(f.s * size)), 0, size - 1);
        const int j = std::clamp(static_cast<int>(std::floor(f.t * size)), 0, size - 1);
        return {texel(t, srgb, i, j, f.face), 0.0};
    }
    const double u = f.s * size - 0.5, v = f.t * size - 0.5;
    const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    const double a = u - i0, b = v - j0;
    // Seamless filtering: a tap across one edge reads the neighbouring face's edge texel.
    const auto tap = [&](int i, int j) {
        if (i >= 0 && i < size && j >= 0 && j < size) return texel(t, srgb, i, j, f.face);
        const lighting::CubeFace n = lighting::select_cube_face(texel_direction(f.face, i, j, size));
        const int ni = std::clamp(static_cast<int>(std::floor(n.s * size)), 0, size - 1);
        const int nj = std::clamp(static_cast<int>(std::floor(n.t * size)), 0, size - 1);
        return texel(t, srgb, ni, nj, n.face);
    };
    CubeSample result;
    const glm::dvec4 t00 = tap(i0, j0), t10 = tap(i0 + 1, j0), t01 = tap(i0, j0 + 1), t11 = tap(i0 + 1, j0 + 1);
    result.value = (1 - a) * (1 - b) * t00 + a * (1 - b) * t10 + (1 - a) * b * t01 + a * b * t11;
    const glm::dvec4 footprint = glm::max(glm::max(t00, t10), glm::max(t01, t11)) - glm::min(glm::min(t00, t10), glm::min(t01, t11));
    result.footprint_spread = std::max({footprint.r, footprint.g, footprint.b, footprint.a});
    const auto outside = [size](int k) { return k < 0 || k >= size; };
    if (!((outside(i0) || outside(i0 + 1)) && (outside(j0) || outside(j0 + 1)))) return result;
    // At a cube corner one tap has no unique neighbour and GL leaves its value to the implementation
    // (the spec recommends the mean of the three corner texels): the spread of the texels nearby.
    glm::dvec4 low(1e300), high(-1e300);
    for (int dj = -1; dj <= 2; ++dj)
        for (int di = -1; di <= 2; ++di) {
            const glm::dvec4 value = tap(std::clamp(i0 + di, -1, size), std::clamp(j0 + dj, -1, size));
            low = glm::min(low, value);
            high = glm::max(high, value);
        }
    const glm::dvec4 spread = high - low;
    result.seam_spread = std::max({spread.r, spread.g, spread.b, spread.a});
    return result;
}

glm::dvec4 sample_3d(const texture::TextureData& t, const effect::SamplerState& s, bool srgb, glm::dvec3 str, double* footprint_spread) {
    if (s.min_filter != GL_NEAREST && s.min_filter != GL_LINEAR)
        throw Error("CPU sampler: mipmapped filtering depends on screen derivatives; use nearest or linear");
    if (s.min_filter != s.mag_filter) throw Error("CPU sampler: min and mag filters must agree");
    const int size[3] = {t.width(), t.height(), t.depth()};
    const GLenum modes[3] = {s.wrap_s, s.wrap_t, s.wrap_r};
    if (s.min_filter == GL_NEAREST) {
        int k[3];
        for (int a = 0; a < 3; ++a) k[a] = wrap(static_cast<int>(std::floor(str[a] * size[a])), size[a], modes[a]);
        if (footprint_spread) *footprint_spread = 0;
        return texel(t, srgb, k[0], k[1], -1, k[2]);
    }
    int low[3], high[3];
    double weight[3];
    for (int a = 0; a < 3; ++a) {
        const double u = str[a] * size[a] - 0.5;
        const int k = static_cast<int>(std::floor(u));
        weight[a] = u - k;
        low[a] = wrap(k, size[a], modes[a]);
        high[a] = wrap(k + 1, size[a], modes[a]);
    }
    glm::dvec4 sum(0.0), lowest(1e300), highest(-1e300);
    for (int corner = 0; corner < 8; ++corner) {
        double w = 1.0;
        int k[3];
        for (int a = 0; a < 3; ++a) {
            const bool upper = (corner >> a) & 1;
            k[a] = upper ? high[a] : low[a];
            w *= upper ? weight[a] : 1.0 - weight[a];
        }
        const glm::dvec4 value = texel(t, srgb, k[0], k[1], -1, k[2]);
        sum += w * value;
        lowest = glm::min(lowest, value);
        highest = glm::max(highest, value);
    }
    if (footprint_spread) {
        const glm::dvec4 spread = highest - lowest;
        *footprint_spread = std::max({spread.r, spread.g, spread.b, spread.a});
    }
    return sum;
}

glm::dvec4 sample_2d(const texture::TextureData& t, const effect::SamplerState& s, bool srgb, glm::dvec2 uv) {
    if (s.min_filter != GL_NEAREST && s.min_filter != GL_LINEAR)
        throw Error("CPU sampler: mipmapped filtering depends on screen derivatives; use nearest or linear");
    if (s.min_filter != s.mag_filter) throw Error("CPU sampler: min and mag filters must agree");
    const int w = t.width(), h = t.height();
    if (s.min_filter == GL_NEAREST) {
        const int i = wrap(static_cast<int>(std::floor(uv.x * w)), w, s.wrap_s);
        const int j = wrap(static_cast<int>(std::floor(uv.y * h)), h, s.wrap_t);
        return texel(t, srgb, i, j);
    }
    const double u = uv.x * w - 0.5, v = uv.y * h - 0.5;
    const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    const double a = u - i0, b = v - j0;
    const int i1 = wrap(i0 + 1, w, s.wrap_s), j1 = wrap(j0 + 1, h, s.wrap_t);
    const int i0w = wrap(i0, w, s.wrap_s), j0w = wrap(j0, h, s.wrap_t);
    return (1 - a) * (1 - b) * texel(t, srgb, i0w, j0w) + a * (1 - b) * texel(t, srgb, i1, j0w) +
           (1 - a) * b * texel(t, srgb, i0w, j1) + a * b * texel(t, srgb, i1, j1);
}

}  // namespace fxview::reference
