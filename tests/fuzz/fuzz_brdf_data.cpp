// Measured BRDFs: the grid CSV and MERL .binary files.
#include "fit/brdf_grid.hpp"
#include "fit/merl.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    const std::string grid = fxview::fuzz::write_input(data, size, "grid.csv");
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::fit::read_brdf_grid(grid); });
    const std::string merl = fxview::fuzz::write_input(data, size, "brdf.binary");
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::fit::read_merl(merl); });
    return 0;
}
