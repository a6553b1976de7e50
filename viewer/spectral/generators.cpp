#include "spectral/generators.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "spectral/spectral_files.hpp"

namespace fxview::spectral {

Spectrum blackbody(double kelvin) {
    if (!(kelvin > 0)) throw UsageError("black body temperature must be positive");
    // Planck: B(l) = 2hc^2 / l^5 / (exp(hc / (l k T)) - 1); constants cancel in the normalisation
    // except c2 = hc/k = 1.4387769e-2 m K (CODATA 2018).
    constexpr double c2 = 1.4387769e-2;
    const auto planck = [kelvin](double nm) {
        const double m = nm * 1e-9;
        return 1.0 / (std::pow(m, 5) * (std::exp(c2 / (m * kelvin)) - 1.0));
    };
    const double at_560 = planck(560.0);
    Spectrum s;
    for (int nm = kMinNm; nm <= kMaxNm; ++nm) s[nm] = planck(nm) / at_560;
    return s;
}

Spectrum cie_daylight(double kelvin, const std::string& colord_dir) {
    if (kelvin < 4000 || kelvin > 25000) throw UsageError("CIE daylight is defined for 4000..25000 K, not " + std::to_string(kelvin));
    const auto basis = read_cgats(colord_dir + "/ref/CIE-1986-daylight-SPD.cmf", Extrapolation::Zero);
    if (basis.size() != 3) throw Error(colord_dir + "/ref/CIE-1986-daylight-SPD.cmf: expected S0, S1, S2");
    // CIE 15:2004 eq. 3.3-3.5: chromaticity of daylight at the CCT, then the weights M1, M2.
    const double t = kelvin, t2 = t * t, t3 = t2 * t;
    const double xd = t <= 7000 ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                                : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
    const double yd = -3.000 * xd * xd + 2.870 * xd - 0.275;
    const double m = 0.0241 + 0.2562 * xd - 0.7341 * yd;
    const double m1 = (-1.3515 - 1.7703 * xd + 5.9114 * yd) / m;
    const double m2 = (0.0300 - 31.4424 * xd + 30.0717 * yd) / m;
    Spectrum s;
    for (int nm = kMinNm; nm <= kMaxNm; ++nm)
        s[nm] = basis[0].spectrum[nm] + m1 * basis[1].spectrum[nm] + m2 * basis[2].spectrum[nm];
    const double at_560 = s.value(560.0);
    return at_560 > 0 ? s.scaled(100.0 / at_560) : s;
}

Spectrum box(double from_nm, double to_nm, double height) {
    Spectrum s;
    for (int nm = kMinNm; nm <= kMaxNm; ++nm) s[nm] = nm >= from_nm && nm <= to_nm ? height : 0.0;
    return s;
}

Spectrum gaussian(double centre_nm, double sigma_nm, double height) {
    if (!(sigma_nm > 0)) throw UsageError("Gaussian width must be positive");
    Spectrum s;
    for (int nm = kMinNm; nm <= kMaxNm; ++nm) s[nm] = height * std::exp(-0.5 * std::pow((nm - centre_nm) / sigma_nm, 2));
    return s;
}

Spectrum ramp(double from_nm, double to_nm) {
    if (!(to_nm > from_nm)) throw UsageError("ramp needs from < to");
    Spectrum s;
    for (int nm = kMinNm; nm <= kMaxNm; ++nm) s[nm] = std::clamp((nm - from_nm) / (to_nm - from_nm), 0.0, 1.0);
    return s;
}

}  // namespace fxview::spectral
