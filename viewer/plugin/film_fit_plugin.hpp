// The `film-fit` plugin: finds the thickness of a thin film (on a dielectric or absorbing
// substrate) whose interference colour has the chromaticity of a target colour, e.g. one picked
// from a photograph or the render (docs/plugins.md). Interference colours repeat with the order,
// so every thickness that matches about as well is reported, not only the best.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "plugin/plugin.hpp"

namespace fxview::plugin {

std::unique_ptr<Plugin> create_film_fit(const effect::Effect& effect, const effect::PluginDeclaration& declaration,
                                        const std::vector<std::string>& texture_dirs);

// The film's reflected colour (CIE XYZ, Y = 1 for a perfect mirror) at `cos0` under `light`:
// Airy's exact reflectance (transfer matrices) per nm over [lower, upper], unpolarised.
struct FilmColourSetup {
    double n0 = 1.0, n1 = 1.33, n2 = 1.5, kappa = 0.0, cos0 = 1.0;
    int lower = 360, upper = 830;
    int observer = 0;           // 0: CIE 1931 2°, 1: CIE 1964 10°
    std::string light = "D65";  // a name or index in spectra/library.txt
};

class FilmColour {
public:
    explicit FilmColour(const FilmColourSetup& setup);  // loads the observer and the light once
    std::array<double, 3> xyz(double thickness_nm) const;

private:
    FilmColourSetup setup_;
    std::vector<std::array<double, 3>> weights_;  // light × CMF per nm from `lower`, normalised: Σ light ȳ = 1
};

// CIE 1976 u'v' chromaticity of an XYZ colour.
std::array<double, 2> uv_prime(const std::array<double, 3>& xyz);
// XYZ of a linear sRGB colour: the inverse of the matrix the spectral effects output through (eq. 9).
std::array<double, 3> linear_srgb_to_xyz(const std::array<double, 3>& rgb);

}  // namespace fxview::plugin
