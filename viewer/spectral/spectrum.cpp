#include "spectral/spectrum.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fxview::spectral {

Spectrum Spectrum::constant(double value) {
    Spectrum s;
    s.values_.fill(value);
    return s;
}

Spectrum Spectrum::from_points(const std::vector<std::pair<double, double>>& points, Extrapolation outside) {
    if (points.empty()) throw Error("spectrum without data");
    for (size_t i = 1; i < points.size(); ++i)
        if (!(points[i].first > points[i - 1].first))
            throw Error("spectrum wavelengths must increase (" + std::to_string(points[i - 1].first) + " then " +
                        std::to_string(points[i].first) + " nm)");
    Spectrum s;
    size_t segment = 0;
    for (int nm = kMinNm; nm <= kMaxNm; ++nm) {
        double v;
        if (nm < points.front().first) v = outside == Extrapolation::Hold ? points.front().second : 0.0;
        else if (nm > points.back().first) v = outside == Extrapolation::Hold ? points.back().second : 0.0;
        else {
            while (segment + 1 < points.size() && points[segment + 1].first < nm) ++segment;
            if (segment + 1 == points.size()) v = points.back().second;
            else {
                const auto& [x0, y0] = points[segment];
                const auto& [x1, y1] = points[segment + 1];
                v = y0 + (y1 - y0) * (nm - x0) / (x1 - x0);
            }
        }
        s[nm] = v;
    }
    return s;
}

double Spectrum::at(int nm) const { return nm < kMinNm || nm > kMaxNm ? 0.0 : (*this)[nm]; }

double Spectrum::value(double nm) const {
    const double f = std::floor(nm);
    const int i = static_cast<int>(f);
    return at(i) + (at(i + 1) - at(i)) * (nm - f);
}

double Spectrum::max() const { return *std::max_element(values_.begin(), values_.end()); }

Spectrum Spectrum::scaled(double factor) const {
    Spectrum s = *this;
    for (double& v : s.values_) v *= factor;
    return s;
}

Spectrum Spectrum::operator*(const Spectrum& other) const {
    Spectrum s = *this;
    for (size_t i = 0; i < values_.size(); ++i) s.values_[i] *= other.values_[i];
    return s;
}

Spectrum summation_comb(const NamedSpectrum& named) {
    if (named.data_step_nm <= 0) throw Error(named.name + ": line spectra need data on a regular whole-nanometre interval");
    Spectrum comb;
    for (int nm = std::max(named.data_start_nm, kMinNm); nm <= std::min(named.data_end_nm, kMaxNm); nm += named.data_step_nm)
        if ((nm - named.data_start_nm) % named.data_step_nm == 0) comb[nm] = named.spectrum[nm] * named.data_step_nm;
    return comb;
}

}  // namespace fxview::spectral
