// Spectral data files: CGATS/IT8 (colord-data's format) and nm,value CSV.
#include "fuzz_input.hpp"
#include "spectral/spectral_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    const std::string path = fxview::fuzz::write_input(data, size, "spectrum.txt");
    using fxview::spectral::Extrapolation;
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::spectral::read_cgats(path, Extrapolation::Hold); });
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::spectral::read_csv(path, Extrapolation::Zero); });
    return 0;
}
