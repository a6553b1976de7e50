// A spectrum sampled every 1 nm from 300 to 900 nm in double precision (pbrt's "densely sampled
// spectrum"). Data given at other spacings is linearly interpolated; outside the data's range the
// spectrum is either held at the nearest end value or zero, as its source asks.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fxview::spectral {

constexpr int kMinNm = 300;
constexpr int kMaxNm = 900;
constexpr int kSampleCount = kMaxNm - kMinNm + 1;

enum class Extrapolation { Hold, Zero };

class Spectrum {
public:
    Spectrum() { values_.fill(0.0); }
    static Spectrum constant(double value);
    // Points (nm, value) in increasing nm order, any spacing; throws Error if unordered or empty.
    static Spectrum from_points(const std::vector<std::pair<double, double>>& points, Extrapolation outside);

    double at(int nm) const;       // 0 outside 300..900
    double value(double nm) const; // linear between the 1 nm samples
    double& operator[](int nm) { return values_[static_cast<size_t>(nm - kMinNm)]; }
    double operator[](int nm) const { return values_[static_cast<size_t>(nm - kMinNm)]; }
    double max() const;
    Spectrum scaled(double factor) const;
    Spectrum operator*(const Spectrum& other) const;

private:
    std::array<double, kSampleCount> values_;
};

struct NamedSpectrum {
    std::string name;
    Spectrum spectrum;
    std::string source;  // where it came from, for `spectra list`
};

}  // namespace fxview::spectral
