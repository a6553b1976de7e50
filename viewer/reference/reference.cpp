#include "reference/reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/error.hpp"
#include "reference/brdf_reference.hpp"
#include "reference/cd_reference.hpp"
#include "reference/debug_reference.hpp"
#include "reference/measured_reference.hpp"
#include "reference/example_reference.hpp"
#include "reference/spectral_reference.hpp"
#include "reference/thin_film_reference.hpp"

namespace fxview::reference {

namespace {

// What the CPU references compute: the shipped effects' ranges of every value whose cost or table
// index grows with it. A user's copy of an effect (found by its file name) may declare wider UI
// ranges; its values are refused here rather than run without end or read beyond a table.
struct Bound {
    const char* name;
    double low, high;
};
constexpr Bound kBounds[] = {{"Tracks", 1, 200},  {"Layers", 1, 16},    {"SeriesOrder", 1, 64}, {"Lower", 360, 830},
                             {"Upper", 360, 830}, {"Steps", 1, 50},     {"Observer", 0, 1},     {"LightSpectrum", 0, 4095},
                             {"ObjectSpectrum", 0, 4095}, {"SubstrateSpectrum", 0, 4095}};

}  // namespace

double ReferenceContext::number(const std::string& name) const {
    const auto found = values.numbers.find(name);
    if (found == values.numbers.end() || found->second.empty()) throw Error("reference: the effect has no parameter " + name);
    const double value = found->second[0];
    if (!std::isfinite(value)) throw Error("reference: " + name + " is not a finite number");
    for (const Bound& bound : kBounds)
        if (name == bound.name && !(value >= bound.low && value <= bound.high))
        {
            char text[200];
            std::snprintf(text, sizeof text, " = %.9g lies outside what the CPU reference computes (%g..%g)", value, bound.low, bound.high);
            throw Error("reference: " + name + text);
        }
    return value;
}

const spectral::PackedTexture& ReferenceContext::generated(const std::string& texture) const {
    const spectral::PackedTexture* packed = resources.generated(texture);
    if (!packed) throw Error("reference: the effect has no generated texture " + texture);
    return *packed;
}

namespace {

struct SamplerData {
    const effect::Parameter* sampler;
    const effect::TextureResource* resource;
    const texture::TextureData* data;
};

SamplerData sampler_data(const ReferenceContext& c, const std::string& name) {
    const effect::Effect& effect = c.resources.effect();
    const effect::Parameter* sampler = effect.find_parameter(name);
    // A sampler with annotations names its own texture; one with sampler_state names the texture block.
    const effect::TextureResource* resource = sampler ? effect.find_texture(sampler->texture.empty() ? name : sampler->texture) : nullptr;
    const texture::TextureData* data = resource ? c.resources.cpu_copy(resource->name) : nullptr;
    if (!data) throw Error("reference: the effect has no sampler " + name + " with loaded texture data");
    return {sampler, resource, data};
}

}  // namespace

glm::dvec4 ReferenceContext::sample_2d(const std::string& sampler, glm::dvec2 uv) const {
    const SamplerData d = sampler_data(*this, sampler);
    return reference::sample_2d(*d.data, d.sampler->sampler, d.resource->srgb, uv);
}

glm::dvec4 ReferenceContext::sample_3d(const std::string& sampler, glm::dvec3 str, double* footprint_spread) const {
    const SamplerData d = sampler_data(*this, sampler);
    return reference::sample_3d(*d.data, d.sampler->sampler, d.resource->srgb, str, footprint_spread);
}

glm::ivec3 ReferenceContext::texture_size(const std::string& sampler) const {
    const SamplerData d = sampler_data(*this, sampler);
    return {d.data->width(), d.data->height(), d.data->depth()};
}

CubeSample ReferenceContext::sample_cube(const std::string& sampler, glm::dvec3 direction) const {
    const SamplerData d = sampler_data(*this, sampler);
    return reference::sample_cube(*d.data, d.sampler->sampler, d.resource->srgb, direction);
}

double normal_sensitivity(const Shader& shade, const ShadingInput& in, const ReferenceContext& c, double angle) {
    const glm::dvec3 n = glm::normalize(in.normal);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(n, helper)), b = glm::cross(n, a);
    const std::array<double, 4> at = shade(in, c);
    double change = 0;
    for (const glm::dvec3& across : {a, -a, b, -b}) {
        ShadingInput turned = in;
        turned.normal = glm::normalize(n + angle * across);
        const std::array<double, 4> moved = shade(turned, c);
        for (size_t i = 0; i < 3; ++i) change = std::max(change, std::abs(moved[i] - at[i]));
    }
    return change;
}

const Reference* find_reference(const std::string& effect_stem, const std::string& technique) {
    // Built once from the reference modules; keys are "effect/technique".
    static const std::map<std::string, Reference> references = [] {
        std::map<std::string, Reference> all;
        for (auto& [name, reference] : spectral_references()) all.emplace("wavelength/" + name, std::move(reference));
        for (auto& [name, reference] : thin_film_references()) all.emplace("thinfilm/" + name, std::move(reference));
        for (auto& [name, reference] : cd_references()) all.emplace("cd/" + name, std::move(reference));
        for (auto& [name, reference] : brdf_references()) all.emplace("analytic/" + name, std::move(reference));
        for (auto& [name, reference] : measured_references()) all.emplace("measured/" + name, std::move(reference));
        for (auto& [name, reference] : debug_references()) all.emplace("debug/" + name, std::move(reference));
        for (auto& [name, reference] : example_references()) all.emplace("textured/" + name, std::move(reference));
        return all;
    }();
    const auto found = references.find(effect_stem + "/" + technique);
    return found == references.end() ? nullptr : &found->second;
}

}  // namespace fxview::reference
