#include "plugin/film_fit_plugin.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "effect/parser.hpp"
#include "optics/thin_film.hpp"
#include "render/effect_resources.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/library.hpp"

namespace fxview::plugin {

FilmColour::FilmColour(const FilmColourSetup& setup) : setup_(setup) {
    if (!(setup.lower >= 360 && setup.upper <= 830 && setup.lower <= setup.upper))
        throw UsageError("film-fit: the wavelength range must lie in 360-830 nm with lower <= upper");
    const spectral::Observer observer = spectral::load_observer(setup.observer == 1 ? "1964" : "1931");
    const spectral::SpectralLibrary library = spectral::load_library(render::spectral_library_path());
    const spectral::Spectrum& light = library.at(setup.light).named.spectrum;
    double ybar = 0;
    for (int nm = setup.lower; nm <= setup.upper; ++nm) {
        const double s = light.at(nm);
        weights_.push_back({s * observer.x.at(nm), s * observer.y.at(nm), s * observer.z.at(nm)});
        ybar += s * observer.y.at(nm);
    }
    if (!(ybar > 0)) throw Error("film-fit: the light '" + setup.light + "' has no energy in " + std::to_string(setup.lower) + "-" +
                                 std::to_string(setup.upper) + " nm");
    for (auto& w : weights_)
        for (double& c : w) c /= ybar;
}

std::array<double, 3> FilmColour::xyz(double thickness_nm) const {
    const optics::Stack stack{setup_.n0, {{setup_.n1, thickness_nm}}, optics::Complex(setup_.n2, setup_.kappa)};
    std::array<double, 3> xyz{0, 0, 0};
    for (int nm = setup_.lower; nm <= setup_.upper; ++nm) {
        const double r = optics::transfer_matrix_reflectance(stack, nm, setup_.cos0);
        const auto& w = weights_[static_cast<size_t>(nm - setup_.lower)];
        for (size_t c = 0; c < 3; ++c) xyz[c] += r * w[c];
    }
    return xyz;
}

std::array<double, 2> uv_prime(const std::array<double, 3>& xyz) {
    const double d = xyz[0] + 15 * xyz[1] + 3 * xyz[2];
    return d > 0 ? std::array<double, 2>{4 * xyz[0] / d, 9 * xyz[1] / d} : std::array<double, 2>{0, 0};
}

std::array<double, 3> linear_srgb_to_xyz(const std::array<double, 3>& rgb) {
    glm::dmat3 to_rgb;  // columns: the images of X, Y and Z
    for (int i = 0; i < 3; ++i) {
        spectral::Vec3 unit{0, 0, 0};
        unit[static_cast<size_t>(i)] = 1;
        const spectral::Vec3 column = spectral::xyz_to_linear_srgb_unclipped(unit);
        to_rgb[i] = glm::dvec3(column[0], column[1], column[2]);
    }
    const glm::dvec3 xyz = glm::inverse(to_rgb) * glm::dvec3(rgb[0], rgb[1], rgb[2]);
    return {xyz.x, xyz.y, xyz.z};
}

namespace {

constexpr double kJustNoticeable = 0.004;  // Δu'v' of a just noticeable chromaticity difference (MacAdam, as commonly used)

class FilmFit final : public Plugin {
public:
    FilmFit(const effect::Effect& effect, const effect::PluginDeclaration& d) : name_(d.name) {
        const auto fail = [&](const std::string& message) { throw fxview::effect::EffectError(d.where, "plugin " + d.name + " (film-fit): " + message); };
        const auto parameter = [&](const std::string& annotation, const char* type, bool required) -> std::string {
            const std::string name = d.text(annotation);
            if (name.empty()) {
                if (required) fail(annotation + " must name a " + type + " parameter");
                return name;
            }
            const effect::Parameter* p = effect.find_parameter(name);
            if (!p) fail(annotation + ": the effect has no parameter '" + name + "'");
            if (p->type != type || p->array_size != 0 || !p->semantic.empty()) fail(annotation + ": " + name + " must be a " + type);
            return name;
        };
        target_ = parameter("Target", "vec3", true);
        vary_ = parameter("Vary", "float", true);
        const effect::Parameter* vary = effect.find_parameter(vary_);
        if (!vary->ui.min || !vary->ui.max || !(*vary->ui.max > *vary->ui.min) || *vary->ui.min < 0)
            fail("Vary: " + vary_ + " needs UIMin >= 0 and UIMax > UIMin, the thickness range searched");
        low_ = *vary->ui.min;
        high_ = *vary->ui.max;
        // The scan samples every 0.5 nm: its cost (and the int count of samples) is bounded here.
        if (high_ - low_ > 20000.0) fail("Vary: " + vary_ + "'s range UIMin..UIMax spans more than 20 000 nm, the scan's budget");
        outer_ = parameter("OuterIndex", "float", true);
        film_ = parameter("FilmIndex", "float", true);
        substrate_ = parameter("SubstrateIndex", "float", true);
        kappa_ = parameter("SubstrateKappa", "float", false);
        light_ = parameter("Light", "int", false);
        observer_ = parameter("Observer", "int", false);
        lower_ = parameter("Lower", "int", false);
        upper_ = parameter("Upper", "int", false);
        technique_ = d.text("Technique");
        if (!technique_.empty() && !effect.find_technique(technique_)) fail("Technique: the effect has no technique '" + technique_ + "'");
        if (const effect::Annotation* angle = d.find("Angle")) {
            if (angle->value.is_string || angle->value.numbers.size() != 1 || !(angle->value.numbers[0] >= 0 && angle->value.numbers[0] < 90))
                fail("Angle must be the angle of incidence in degrees, 0 to below 90");
            angle_deg_ = angle->value.numbers[0];
        }
    }

    std::string name() const override { return name_; }
    std::string type() const override { return "film-fit"; }
    std::string technique() const override { return technique_; }
    std::string description() const override {
        char text[200];
        std::snprintf(text, sizeof text, "find the %s (%.0f-%.0f nm) whose interference colour at %.0f deg has the chromaticity of %s",
                      vary_.c_str(), low_, high_, angle_deg_, target_.c_str());
        return text;
    }
    std::vector<std::string> inputs() const override {
        std::vector<std::string> in{target_, outer_, film_, substrate_};
        for (const std::string& p : {kappa_, light_, observer_, lower_, upper_})
            if (!p.empty()) in.push_back(p);
        return in;
    }
    std::vector<std::string> outputs() const override { return {vary_}; }

    Result run(const effect::ParameterValues& values, const Reporter& reporter, const std::string& user_file) const override {
        if (!user_file.empty()) throw UsageError("film-fit reads no data file");
        const auto number = [&](const std::string& name, double fallback) {
            if (name.empty()) return fallback;
            const auto found = values.numbers.find(name);
            return found == values.numbers.end() || found->second.empty() ? fallback : found->second[0];
        };
        FilmColourSetup setup;
        setup.n0 = number(outer_, 1.0);
        setup.n1 = number(film_, 1.33);
        setup.n2 = number(substrate_, 1.5);
        setup.kappa = number(kappa_, 0.0);
        setup.observer = static_cast<int>(number(observer_, 0));
        setup.lower = static_cast<int>(number(lower_, 360));
        setup.upper = static_cast<int>(number(upper_, 830));
        setup.light = std::to_string(static_cast<int>(number(light_, 5)));  // 5: D65 in spectra/library.txt
        const double sin0 = std::sin(angle_deg_ * 3.14159265358979323846 / 180.0);
        setup.cos0 = std::sqrt(1.0 - sin0 * sin0);
        const FilmColour colour(setup);

        const auto& target_rgb = values.numbers.at(target_);
        const std::array<double, 3> target_xyz = linear_srgb_to_xyz({target_rgb[0], target_rgb[1], target_rgb[2]});
        if (!(target_xyz[1] > 0)) throw UsageError("film-fit: the target colour " + target_ + " is black: it has no chromaticity");
        const std::array<double, 2> target_uv = uv_prime(target_xyz);
        const auto distance = [&](double d) {
            const std::array<double, 2> uv = uv_prime(colour.xyz(d));
            return std::hypot(uv[0] - target_uv[0], uv[1] - target_uv[1]);
        };

        // A scan at 0.5 nm (interference colours change over ~10 nm), then golden-section search in
        // every local minimum: the best and the other orders that match about as well.
        const double step = 0.5;
        const int count = static_cast<int>(std::floor((high_ - low_) / step)) + 1;
        std::vector<double> cost(static_cast<size_t>(count));
        size_t best_index = 0;
        for (int i = 0; i < count; ++i) {
            cost[static_cast<size_t>(i)] = distance(low_ + step * i);
            if (cost[static_cast<size_t>(i)] < cost[best_index]) best_index = static_cast<size_t>(i);
            if (i % 200 == 0)
                reporter.update({0.9 * i / count, "scan", {{vary_, {low_ + step * static_cast<double>(best_index)}}}, cost[best_index]});
        }
        struct Match {
            double thickness, distance;
        };
        std::vector<Match> minima;
        for (int i = 0; i < count; ++i) {
            const double c = cost[static_cast<size_t>(i)];
            const bool left = i == 0 || c <= cost[static_cast<size_t>(i - 1)], right = i == count - 1 || c < cost[static_cast<size_t>(i + 1)];
            if (!(left && right)) continue;
            double from = low_ + step * std::max(i - 1, 0), to = low_ + step * std::min(i + 1, count - 1);
            const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
            for (int k = 0; k < 40 && to - from > 1e-4; ++k) {
                const double p = to - ratio * (to - from), q = from + ratio * (to - from);
                if (distance(p) < distance(q)) to = q;
                else from = p;
            }
            const double d = 0.5 * (from + to);
            minima.push_back({d, std::min(distance(d), c)});
        }
        std::sort(minima.begin(), minima.end(), [](const Match& a, const Match& b) { return a.distance < b.distance; });
        const Match best = minima.front();
        reporter.update({1.0, "refine", {{vary_, {best.thickness}}}, best.distance});

        Result result;
        result.parameters = {{vary_, {best.thickness}}};
        result.technique = technique_;
        const double luminance = colour.xyz(best.thickness)[1];
        char line[256];
        std::snprintf(line, sizeof line, "%s = %.2f nm: chromaticity distance du'v' %.5f to %s (%s)", vary_.c_str(), best.thickness,
                      best.distance, target_.c_str(), best.distance <= kJustNoticeable ? "below a just noticeable difference" : "visibly different");
        result.summary.push_back(line);
        std::snprintf(line, sizeof line, "film reflectance Y %.4f (the target's luminance is not matched: brightness depends on the light)",
                      luminance);
        result.summary.push_back(line);
        result.numbers = {{"thickness_nm", best.thickness}, {"delta_uv", best.distance}, {"film_luminance", luminance}};
        if (best.distance > kJustNoticeable) {
            result.converged = false;
            result.warnings.push_back("no thickness in the range reproduces the target's chromaticity (du'v' " + std::to_string(best.distance) +
                                      " > 0.004): the film's indices cannot make this colour");
        }
        std::string others;
        int alternatives = 0;
        for (size_t i = 1; i < minima.size() && best.distance <= kJustNoticeable; ++i)
            if (minima[i].distance <= std::max(2.0 * best.distance, kJustNoticeable)) {
                char text[64];
                std::snprintf(text, sizeof text, "%s%.1f nm (du'v' %.4f)", alternatives ? ", " : "", minima[i].thickness, minima[i].distance);
                others += text;
                ++alternatives;
            }
        if (alternatives > 0) {
            result.warnings.push_back("interference colours repeat: " + std::to_string(alternatives) +
                                      " other thicknesses match about as well: " + others);
            result.numbers["alternatives"] = alternatives;
        }
        return result;
    }

private:
    std::string name_, target_, vary_, outer_, film_, substrate_, kappa_, light_, observer_, lower_, upper_, technique_;
    double low_ = 0, high_ = 0, angle_deg_ = 0;
};

}  // namespace

std::unique_ptr<Plugin> create_film_fit(const effect::Effect& effect, const effect::PluginDeclaration& declaration,
                                        const std::vector<std::string>&) {
    return std::make_unique<FilmFit>(effect, declaration);
}

}  // namespace fxview::plugin
