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
    // The data's own sampling when it is regular on whole nanometres (e.g. 380, 385, ... 780 for
    // colord's illuminants); step 0 when irregular or generated.
    int data_start_nm = 0, data_end_nm = 0, data_step_nm = 0;
};

// CIE 15's colorimetry of line spectra (fluorescent lamps): tristimulus values by summation at the
// data's own interval, not by interpolating between lines. As a 1 nm spectrum this is a comb: the
// value times the interval at each data wavelength, zero between, so that every 1 nm integration
// (CPU and GPU) sums exactly what CIE 15 sums. Throws Error when the data has no regular interval.
Spectrum summation_comb(const NamedSpectrum& named);

}  // namespace fxview::spectral
