#include "app/film_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "reference/film_fourier.hpp"
#include "spectral/fourier_table.hpp"
#include "spectral/color_difference.hpp"
#include "spectral/level_of_detail.hpp"
#include "spectral/library.hpp"

namespace fxview::app {
namespace {

struct Substrate {
    const char* name;
    optics::Complex index;
    bool metal;
};

// Free film (soap), glass, silicon and two metals at mid-visible wavelengths (constant indices: the
// series needs wavelength-independent coefficients).
constexpr Substrate kSubstrates[] = {{"air (free film)", {1.0, 0.0}, false}, {"glass 1.5", {1.5, 0.0}, false},
                                     {"silicon 4.0+0.03i", {4.0, 0.03}, false}, {"aluminium 1.2+7.0i", {1.2, 7.0}, true},
                                     {"gold 0.27+2.9i", {0.27, 2.9}, true}};
constexpr double kFilmIndices[] = {1.1, 1.33, 1.5, 1.8, 2.1, 2.5};

// ΔE statistics of one order, split by substrate kind (dielectric, metal), thickness (≤ 1000 nm,
// beyond) and angle (≤ 80°, beyond: near grazing the series converges slowly, |x| → 1).
constexpr size_t kBands = 8;
struct Bands {
    std::array<double, kBands> sum{}, max{};
    std::array<long, kBands> count{}, fallbacks{};
    Bands& operator+=(const Bands& o) {
        for (size_t i = 0; i < kBands; ++i) {
            fallbacks[i] += o.fallbacks[i];
            sum[i] += o.sum[i];
            max[i] = std::max(max[i], o.max[i]);
            count[i] += o.count[i];
        }
        return *this;
    }
};

// One Bands per order studied.
struct OrderBands {
    std::vector<Bands> bands;
    OrderBands& operator+=(const OrderBands& o) {
        if (bands.empty()) bands.resize(o.bands.size());
        for (size_t k = 0; k < o.bands.size(); ++k) bands[k] += o.bands[k];
        return *this;
    }
};

const char* kKinds[] = {"dielectric", "metal"};
const char* kBandNames[] = {"d <= 1000 nm, angle <= 80", "d <= 1000 nm, angle > 80", "d > 1000 nm, angle <= 80", "d > 1000 nm, angle > 80"};

}  // namespace

int run_film_error(const FilmErrorOptions& o) {
    if (o.orders.empty()) throw UsageError("film-error: give at least one order");
    for (const int order : o.orders)
        if (order < 0 || order > 64) throw UsageError("film-error: orders lie in 0..64");
    if (!(o.thickness_step > 0) || !(o.max_thickness > 0) || o.angle_step < 1) throw UsageError("film-error: steps must be positive");
    const spectral::SpectralLibrary library = spectral::load_library(o.library);
    const int light_index = library.index_of(o.light);
    if (light_index < 0) throw UsageError("film-error: no spectrum '" + o.light + "' in the library (fxview spectra list)");
    const spectral::Spectrum light = library.spectra()[static_cast<size_t>(light_index)].spectrum;
    const spectral::Observer observer = spectral::load_observer(o.observer);
    const spectral::SensitivityTransform transform(observer, light);
    const spectral::Vec3 white = transform.white();
    // The shipped techniques' rule (FresnelFourier / BubbleFourier: the GPU's table, at most 16 terms,
    // the exact sum where the series does not serve), studied beside the plain orders.
    const spectral::PackedTexture table =
        spectral::fourier_table(library.spectra(), spectral::load_observer("1931"), spectral::load_observer("1964"));
    const int observer_row = o.observer == "1964" ? 1 : 0;
    spectral::Vec3 table_white{};
    for (size_t c = 0; c < 3; ++c) table_white[c] = spectral::fourier_lookup(table, observer_row, light_index, 0.0)[c].real();
    const size_t technique_row = o.orders.size();

    std::vector<double> thicknesses;
    for (double d = 0; d <= o.max_thickness + 1e-9; d += o.thickness_step) thicknesses.push_back(d);
    std::vector<double> angles;
    for (int a = 0; a < 90; a += o.angle_step) angles.push_back(a);
    angles.push_back(89);
    const OrderBands per_order = parallel_sum<OrderBands>(thicknesses.size(), [&](size_t begin, size_t end) {
        OrderBands result;
        std::vector<Bands>& bands = result.bands;
        bands.resize(o.orders.size() + 1);
        for (size_t t = begin; t < end; ++t)
            for (const Substrate& substrate : kSubstrates)
                for (const double index : kFilmIndices)
                    for (const double angle : angles) {
                        const reference::SingleFilm film{1.0, index, substrate.index, thicknesses[t], std::cos(angle * std::numbers::pi / 180.0)};
                        const spectral::Vec3 exact = spectral::xyz_to_lab(reference::film_xyz_exact(observer, light, film), white);
                        const size_t band = (substrate.metal ? 4 : 0) + (thicknesses[t] > 1000 ? 2 : 0) + (angle > 80 ? 1 : 0);
                        const auto add = [&](size_t k, double e) {
                            bands[k].sum[band] += e;
                            bands[k].max[band] = std::max(bands[k].max[band], e);
                            ++bands[k].count[band];
                        };
                        for (size_t k = 0; k < o.orders.size(); ++k)
                            add(k, spectral::delta_e_2000(exact, spectral::xyz_to_lab(reference::film_xyz_fourier(transform, film, o.orders[k]), white)));
                        const auto rule = reference::film_xyz_fourier_table(table, observer_row, light_index, film, {});
                        add(technique_row, rule ? spectral::delta_e_2000(exact, spectral::xyz_to_lab(*rule, table_white)) : 0.0);
                        if (!rule) ++bands[technique_row].fallbacks[band];
                    }
        return result;
    }, 1);
    nlohmann::json rows = nlohmann::json::array();
    if (!o.json) {
        std::printf("CIEDE2000 of the Fourier series against the 1 nm transfer-matrix integral (%s light, CIE %s observer)\n",
                    o.light.c_str(), o.observer.c_str());
        std::printf("%zu thicknesses 0-%g nm, %zu angles 0-89 deg, film indices 1.1-2.5, substrates: dielectric (air = free film, glass, "
                    "silicon), metal (aluminium, gold)\n",
                    thicknesses.size(), o.max_thickness, angles.size());
        std::printf("| substrate | order | %s | %s | %s | %s |\n| --- | --- | --- | --- | --- | --- |\n", kBandNames[0], kBandNames[1],
                    kBandNames[2], kBandNames[3]);
    }
    for (size_t kind = 0; kind < 2; ++kind)
        for (size_t k = 0; k <= o.orders.size(); ++k) {
            const Bands& b = per_order.bands[k];
            const bool technique = k == technique_row;
            nlohmann::json row{{"substrate", kKinds[kind]}};
            if (technique) row["order"] = "technique";
            else row["order"] = o.orders[k];
            std::string line = std::string("| ") + kKinds[kind] + " | " + (technique ? "technique" : std::to_string(o.orders[k])) + " |";
            for (size_t i = 0; i < 4; ++i) {
                const size_t band = kind * 4 + i;
                const double mean = b.count[band] ? b.sum[band] / b.count[band] : 0.0;
                const double exact_share = b.count[band] ? static_cast<double>(b.fallbacks[band]) / b.count[band] : 0.0;
                row[kBandNames[i]] = {{"mean", mean}, {"max", b.max[band]}, {"cases", b.count[band]}};
                if (technique) row[kBandNames[i]]["exact_fallback_share"] = exact_share;
                char cell[96];
                if (technique) std::snprintf(cell, sizeof cell, " %.3g / %.3g (%.1f %% exact) |", mean, b.max[band], 100.0 * exact_share);
                else std::snprintf(cell, sizeof cell, " %.3g / %.3g |", mean, b.max[band]);
                line += cell;
            }
            rows.push_back(row);
            if (!o.json) std::printf("%s\n", line.c_str());
        }
    if (o.json) std::cout << nlohmann::json{{"light", o.light}, {"observer", o.observer}, {"orders", rows}}.dump() << "\n";
    else
        std::printf("(each cell: mean / max; order N: the plain series of N terms with the exact transform; technique: what "
                    "FresnelFourier and BubbleFourier compute, the GPU's table with at most 16 terms and the exact sum where "
                    "the series does not serve, whose share is given)\n");
    return 0;
}

}  // namespace fxview::app
