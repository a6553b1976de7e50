// `fxview spectra film-error`: how far a film's colour by the truncated Fourier series (Belcour &
// Barla; reference/film_fourier.hpp) lies from the 1 nm transfer-matrix integral, as CIEDE2000 over
// thickness, angle, film index and substrate, per series order (docs/thin-films.md).
#pragma once
#include <string>
#include <vector>

namespace fxview::app {

struct FilmErrorOptions {
    std::vector<int> orders{1, 2, 3, 4, 6, 8};
    std::string light = "D65", observer = "1931", library;
    double thickness_step = 20, max_thickness = 2000;
    int angle_step = 10;
    bool json = false;
};

int run_film_error(const FilmErrorOptions& options);

}  // namespace fxview::app
