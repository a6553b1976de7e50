#include "reference/spectral_integration.hpp"

#include <algorithm>

namespace fxview::reference {

SpectralSetup spectral_setup(const ReferenceContext& c) {
    SpectralSetup s{};
    const bool bytes = c.number("ByteCmf") != 0.0;
    s.cmf = &c.generated(bytes ? "CmfBytes" : "CmfFloat");
    s.spectra = &c.generated("Spectra");
    s.cmf_unit = 1.0 / s.cmf->scale;
    s.observer = static_cast<int>(c.number("Observer"));
    s.lower = static_cast<int>(c.number("Lower"));
    s.upper = static_cast<int>(c.number("Upper"));
    s.steps = std::max(1, static_cast<int>(c.number("Steps")));
    s.k = c.number("K");
    s.brightness = c.number("Brightness");
    s.mapping = static_cast<int>(c.number("OutputMode"));
    return s;
}

double output_gain(const SpectralSetup& s, double reference_brightness) {
    double ybar = 0;
    for (int nm = s.lower; nm <= s.upper; nm += s.steps) ybar += spectral::cmf_value(*s.cmf, s.observer, nm)[1] * s.cmf_unit;
    const double k_gain = s.k > 0 && ybar > 0 ? s.k * ybar : 1.0;  // a user's k against the automatic 1 / sum ybar
    return std::max(1.0, s.brightness * k_gain / reference_brightness);
}

std::array<double, 4> to_rgba(const spectral::Vec3& xyz, int mode) {
    const auto mapping = mode == 1 ? spectral::GamutMapping::Desaturate
                         : mode == 2 ? spectral::GamutMapping::Scale
                         : mode == 3 ? spectral::GamutMapping::Unbounded
                                     : spectral::GamutMapping::Clip;
    const spectral::Vec3 rgb = spectral::xyz_to_linear_srgb(xyz, mapping);
    return {rgb[0], rgb[1], rgb[2], 1.0};
}

SpectralSetup every_nm_setup(const ReferenceContext& c) {
    SpectralSetup every_nm = spectral_setup(c);
    every_nm.cmf = &c.generated("CmfFloat");
    every_nm.cmf_unit = 1.0;
    every_nm.lower = spectral::kCmfFirstNm;
    every_nm.upper = spectral::kCmfLastNm;
    every_nm.steps = 1;
    every_nm.k = 0;
    return every_nm;
}

}  // namespace fxview::reference
