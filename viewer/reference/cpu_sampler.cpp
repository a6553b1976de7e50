#include "reference/cpu_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
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

glm::dvec4 texel(const texture::TextureData& t, bool srgb, int i, int j) {
    float rgba[4];
    // GL row j counts from the bottom; the data keeps the image's top row first.
    texture::read_texel(t, 0, 0, i, t.height() - 1 - j, rgba);
    glm::dvec4 value(rgba[0], rgba[1], rgba[2], rgba[3]);
    if (srgb)
        for (int c = 0; c < 3; ++c) value[c] = image::srgb_decode(static_cast<float>(value[c]));
    return value;
}

}  // namespace

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
