#include "lighting/image_spectral_form.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "spectral/rgb_uplift.hpp"

namespace fxview::lighting {

namespace {

constexpr int kCount = SpectralForm::kLastNm - SpectralForm::kFirstNm + 1;
constexpr int kShapeStep = 5;  // nm between the samples the principal shapes are found from (smooth sigmoids)
constexpr int kShapeCount = (SpectralForm::kLastNm - SpectralForm::kFirstNm) / kShapeStep + 1;

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

struct Sample {
    glm::dvec3 rgb;
    double weight;  // in the second moments
};

// The cube at 32² per face (means of its texels) and the discs: what the shapes are found from.
std::vector<Sample> samples_of(const Environment& environment) {
    FloatCube cube = environment.radiance;
    while (cube.size > 32) cube = downsample(cube);
    std::vector<double> lums;
    for (const auto& face : cube.faces)
        for (const glm::vec3& c : face) lums.push_back(luminance(glm::dvec3(c)));
    std::nth_element(lums.begin(), lums.begin() + static_cast<long>(lums.size() / 2), lums.end());
    const double median = lums[lums.size() / 2];
    std::vector<Sample> samples;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < cube.size; ++y)
            for (int x = 0; x < cube.size; ++x) {
                const glm::dvec3 rgb(cube.at(face, x, y));
                const double l = luminance(rgb);
                // Near-black texels' colour is mostly noise: they fade out below a tenth of the median.
                if (l > 0.0) samples.push_back({rgb, texel_solid_angle(x, y, cube.size) * l / (l + 0.1 * median)});
            }
    for (const DiscLight& disc : environment.discs)
        if (luminance(disc.radiance) > 0.0) samples.push_back({disc.radiance, std::numbers::pi});
    return samples;
}

// The reflectance shape of a colour (its uplift's sigmoid) every kShapeStep nm.
Eigen::VectorXd shape_of(const glm::dvec3& rgb) {
    const spectral::UpliftedRadiance u = spectral::uplift_radiance({rgb.r, rgb.g, rgb.b});
    Eigen::VectorXd s(kShapeCount);
    for (int i = 0; i < kShapeCount; ++i) s[i] = u.shape(SpectralForm::kFirstNm + i * kShapeStep);
    return s;
}

// XYZ of a 1 nm spectrum over 360-830 (constant 1 has Y = 1: SpectralForm's luminance).
spectral::Vec3 xyz_of(const std::vector<double>& s) {
    static const spectral::Observer observer = spectral::load_observer("1931");
    spectral::Spectrum spectrum;
    for (int nm = SpectralForm::kFirstNm; nm <= SpectralForm::kLastNm; ++nm) spectrum[nm] = s[static_cast<size_t>(nm - SpectralForm::kFirstNm)];
    return spectral::spectrum_to_xyz(spectrum, observer);
}

const spectral::UpliftFit& uplift_fit() {
    static const spectral::UpliftFit fit(spectral::load_observer("1931"));
    return fit;
}

// The luminance of each sRGB primary at 1 (the second row of eq. 9's inverse).
glm::dvec3 primary_luminances() {
    Eigen::Matrix3d to_rgb;
    for (int c = 0; c < 3; ++c) {
        spectral::Vec3 xyz{0.0, 0.0, 0.0};
        xyz[static_cast<size_t>(c)] = 1.0;
        const spectral::Vec3 rgb = spectral::xyz_to_linear_srgb_unclipped(xyz);
        for (int r = 0; r < 3; ++r) to_rgb(r, c) = rgb[static_cast<size_t>(r)];
    }
    const Eigen::Matrix3d to_xyz = to_rgb.inverse();
    return {to_xyz(1, 0), to_xyz(1, 1), to_xyz(1, 2)};
}

}  // namespace

void add_image_spectral_form(Environment& environment) {
    const std::vector<Sample> samples = samples_of(environment);
    // Second moments of the shapes, and a little of the primaries' and secondaries' so that the span
    // has three dimensions even for a grey or single-coloured image.
    Eigen::MatrixXd moments = Eigen::MatrixXd::Zero(kShapeCount, kShapeCount);
    double total = 0.0;
    for (const Sample& s : samples) {
        const Eigen::VectorXd shape = shape_of(s.rgb);
        moments.noalias() += s.weight * shape * shape.transpose();
        total += s.weight;
    }
    const glm::dvec3 hues[] = {{1, 0.2, 0.2}, {0.2, 1, 0.2}, {0.2, 0.2, 1}, {1, 1, 0.2}, {0.2, 1, 1}, {1, 0.2, 1}};
    for (const glm::dvec3& hue : hues) {
        const Eigen::VectorXd shape = shape_of(hue);
        moments.noalias() += 1e-3 * std::max(total, 1.0) * shape * shape.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(moments);
    // The three largest (eigenvalues come in increasing order), as 1 nm spectra under D65.
    const spectral::UpliftFit& fit = uplift_fit();
    std::array<std::vector<double>, 3> principal;
    std::array<spectral::Vec3, 3> rgb_of;
    for (int k = 0; k < 3; ++k) {
        const Eigen::VectorXd v = solver.eigenvectors().col(kShapeCount - 1 - k);
        auto& s = principal[static_cast<size_t>(k)];
        for (int nm = SpectralForm::kFirstNm; nm <= SpectralForm::kLastNm; ++nm) {
            const int i = std::min((nm - SpectralForm::kFirstNm) / kShapeStep, kShapeCount - 2);
            const double t = (nm - SpectralForm::kFirstNm - i * kShapeStep) / double(kShapeStep);
            s.push_back(((1.0 - t) * v[i] + t * v[i + 1]) * fit.illuminant()[static_cast<size_t>(nm - SpectralForm::kFirstNm)]);
        }
        rgb_of[static_cast<size_t>(k)] = spectral::xyz_to_linear_srgb_unclipped(xyz_of(s));
    }
    // Recombine: the spectra of the span whose colours are the primaries.
    Eigen::Matrix3d colours;
    for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) colours(c, k) = rgb_of[static_cast<size_t>(k)][static_cast<size_t>(c)];
    const Eigen::Matrix3d mix = colours.inverse();  // column c: how much of each principal spectrum makes primary c
    SpectralForm form;
    const glm::dvec3 lum_of_primary = primary_luminances();
    for (int c = 0; c < 3; ++c) {
        std::vector<double> s(kCount, 0.0);
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < kCount; ++i) s[static_cast<size_t>(i)] += mix(k, c) * principal[static_cast<size_t>(k)][static_cast<size_t>(i)];
        for (double& v : s) v /= lum_of_primary[c];  // luminance 1: its colour is the primary's, whose luminance that is
        form.spectra[static_cast<size_t>(c)] = std::move(s);
    }
    const auto weigh = [lum_of_primary](FloatCube cube) {
        for (auto& face : cube.faces)
            for (glm::vec3& c : face) c = glm::vec3(glm::dvec3(c) * lum_of_primary);
        return cube;
    };
    form.weights = weigh(environment.radiance_with_discs());
    form.map_weights = weigh(environment.radiance);
    for (DiscLight disc : environment.discs) {
        disc.radiance *= lum_of_primary;
        form.discs.push_back(disc);
    }
    // The ground truth: the image's texels (bilinear), the discs sharp, each colour uplifted whole.
    form.exact = [radiance = environment.radiance, discs = environment.discs, lum_of_primary](const glm::dvec3& direction) {
        const glm::dvec3 d = glm::normalize(direction);
        glm::dvec3 rgb(sample_bilinear(radiance, d));
        for (const DiscLight& disc : discs)
            if (glm::dot(d, disc.direction) > std::cos(disc.angular_radius)) rgb += disc.radiance;
        return rgb * lum_of_primary;
    };
    form.exact_radiance = [lum_of_primary, illuminant = fit.illuminant()](const glm::dvec3& weights, int nm) {
        // Ground truths ask for one direction's spectrum at every nm in turn: uplift it once.
        thread_local glm::dvec3 last(-1.0);
        thread_local spectral::UpliftedRadiance uplifted;
        if (weights != last) {
            const glm::dvec3 rgb = weights / lum_of_primary;
            uplifted = spectral::uplift_radiance({rgb.r, rgb.g, rgb.b});
            last = weights;
        }
        return uplifted.value(nm, illuminant);
    };
    form.texels_only = true;
    environment.spectral = std::move(form);
    environment.spectral->projection_error = projection_error(environment);
}

double projection_error(const Environment& environment) {
    if (!environment.spectral) return 0.0;
    const SpectralForm& form = *environment.spectral;
    const glm::dvec3 lum_of_primary = primary_luminances();
    double difference = 0.0, magnitude = 0.0;
    for (const Sample& s : samples_of(environment)) {
        const spectral::UpliftedRadiance u = spectral::uplift_radiance({s.rgb.r, s.rgb.g, s.rgb.b});
        const double scale = s.weight / (luminance(s.rgb) * luminance(s.rgb));  // each spectrum at luminance 1
        for (int nm = SpectralForm::kFirstNm; nm <= SpectralForm::kLastNm; ++nm) {
            const size_t i = static_cast<size_t>(nm - SpectralForm::kFirstNm);
            const double full = u.value(nm, uplift_fit().illuminant());
            double projected = 0.0;
            for (int c = 0; c < 3; ++c) projected += s.rgb[c] * lum_of_primary[c] * form.spectra[static_cast<size_t>(c)][i];
            difference += scale * (full - projected) * (full - projected);
            magnitude += scale * full * full;
        }
    }
    return magnitude > 0.0 ? std::sqrt(difference / magnitude) : 0.0;
}

}  // namespace fxview::lighting
