// `fxview spectra ...`: the seed's SpectralLibrarian and CIEXYZ2Texture as subcommands.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/film_error.hpp"
#include "app/spectrum_plot.hpp"
#include "app/value_parsing.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "image/image_file.hpp"
#include "optics/thin_film.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/level_of_detail.hpp"
#include "spectral/library.hpp"
#include "spectral/packing.hpp"
#include "spectral/color_difference.hpp"
#include "spectral/rgb_uplift.hpp"
#include "lighting/environment_sources.hpp"

namespace fxview::app {

namespace {

std::string default_library() {
    const char* override_dir = std::getenv("FXVIEW_SPECTRA_DIR");
    return std::string(override_dir ? override_dir : FXVIEW_SOURCE_SPECTRA_DIR) + "/library.txt";
}

texture::PixelFormat parse_storage(const std::string& text) {
    const std::string f = to_lower(text);
    if (f == "8" || f == "rgba8") return texture::PixelFormat::RGBA8;
    if (f == "16f" || f == "rgba16f") return texture::PixelFormat::RGBA16F;
    if (f == "32f" || f == "rgba32f") return texture::PixelFormat::RGBA32F;
    throw UsageError("--format: expected 8, 16F or 32F, got '" + text + "'");
}

// Writes a packed texture: 8-bit as PNG (linear values, no sRGB curve), float as EXR or PFM.
void write_texture(const spectral::PackedTexture& packed, const std::string& path) {
    const std::string extension = lower_extension(path);
    const bool bytes = packed.texture.format == texture::PixelFormat::RGBA8;
    if (bytes != (extension == ".png"))
        throw UsageError(path + ": 8-bit textures are written as .png, float ones as .exr or .pfm");
    image::FloatImage out(packed.texture.width(), packed.texture.height(), 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) texture::read_texel(packed.texture, 0, 0, x, y, out.pixel(x, y));
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    image::write_image(path, out, image::Encoding::Linear);
}

// A spectrum named on the command line: a library name first, then any source expression or file.
spectral::NamedSpectrum find_spectrum(const std::string& name, const std::string& library_path) {
    const spectral::SpectralLibrary library = spectral::load_library(library_path);
    if (library.index_of(name) >= 0) return library.at(name).named;
    return spectral::spectrum_from_source(name, ".");
}

spectral::GamutMapping parse_mapping(const std::string& text) {
    if (text == "clip") return spectral::GamutMapping::Clip;
    if (text == "desaturate") return spectral::GamutMapping::Desaturate;
    if (text == "scale") return spectral::GamutMapping::Scale;
    throw UsageError("--mapping: expected clip, desaturate or scale, got '" + text + "'");
}

}  // namespace

CommandRunner add_spectra_command(CLI::App& app) {
    struct Options {
        std::string library = default_library();
        bool json = false;
        std::string format = "32F", out, observer = "1931", mapping = "clip";
        std::vector<std::string> names;
        int lower = 360, upper = 830, step = 1;
        bool normalise = false;
        std::string size = "900x520";
        std::string light = "D65";
        double film_nm = -1;
        std::string rgb, environment;
    };
    auto o = std::make_shared<Options>();
    CLI::App* spectra = app.add_subcommand("spectra", "Spectral library tools: list, xyz, pack, cmf, plot, lod, film-error, uplift");
    spectra->require_subcommand(1);
    spectra->add_option("--library", o->library, "Spectral library file")->capture_default_str();

    CLI::App* list = spectra->add_subcommand("list", "List the library's spectra with their index");
    list->add_flag("--json", o->json, "Print JSON");

    CLI::App* xyz = spectra->add_subcommand("xyz", "XYZ, chromaticity and sRGB of a spectrum");
    xyz->add_option("spectrum", o->names, "Library name, file (.csv, CGATS) or source (daylight:6500, ...)")->required()->expected(1);
    xyz->add_option("--observer", o->observer, "1931 (2 degree) or 1964 (10 degree)")->capture_default_str();
    xyz->add_option("--lower", o->lower, "Lowest wavelength (nm)")->capture_default_str();
    xyz->add_option("--upper", o->upper, "Highest wavelength (nm)")->capture_default_str();
    xyz->add_option("--step", o->step, "Wavelength step (nm)")->capture_default_str()->check(CLI::Range(1, 100));
    xyz->add_option("--mapping", o->mapping, "Out-of-gamut handling: clip, desaturate, scale")->capture_default_str();
    xyz->add_flag("--json", o->json, "Print JSON");

    CLI::App* uplift = spectra->add_subcommand("uplift", "The spectrum fxview gives a linear sRGB colour (Jakob & Hanika 2019), and its colour back");
    uplift->add_option("rgb", o->rgb, "Linear sRGB R,G,B (a radiance: any scale; negative channels count as 0)");
    uplift->add_option("--environment", o->environment,
                       "Instead: an environment (an image, or studio/sky/furnace): the three spectra the spectral effects see it by, and "
                       "how far they are from its texels' own uplifted spectra");
    uplift->add_option("--out,-o", o->out, "Also write the spectrum (or the environment's three) at 1 nm, 360-830, as CSV");
    uplift->add_flag("--json", o->json, "Print JSON");

    CLI::App* pack = spectra->add_subcommand("pack", "Pack the library into the spectrum texture (512 samples, 324-835 nm)");
    pack->add_option("--format", o->format, "8, 16F or 32F")->capture_default_str();
    pack->add_option("--out,-o", o->out, "Output: .png for 8-bit, .exr or .pfm for float")->required();

    CLI::App* cmf = spectra->add_subcommand("cmf", "Write the CMF texture (rows: CIE 1931 2 deg, CIE 1964 10 deg)");
    cmf->add_option("--format", o->format, "8, 16F or 32F")->capture_default_str();
    cmf->add_option("--out,-o", o->out, "Output: .png for 8-bit, .exr or .pfm for float")->required();

    CLI::App* plot = spectra->add_subcommand("plot", "Draw spectra as a chart");
    plot->add_option("spectra", o->names, "Library names, files or sources")->required();
    plot->add_option("--out,-o", o->out, "PNG file")->required();
    plot->add_option("--lower", o->lower, "Lowest wavelength (nm)")->capture_default_str();
    plot->add_option("--upper", o->upper, "Highest wavelength (nm)")->capture_default_str();
    plot->add_flag("--normalise", o->normalise, "Scale each spectrum to a peak of 1");
    plot->add_option("--size", o->size, "Image size WxH")->capture_default_str();

    // Table 9's question (DOMAIN.md §5): how far each level's colour lies from the full sum, in ΔE*ab
    // under the light (its white at the same level), for an object reflectance or a thin film.
    const auto run_lod = [](const Options& opt) {
        spectral::Spectrum object;
        std::string object_name;
        if (opt.film_nm >= 0) {
            if (!opt.names.empty()) throw UsageError("spectra lod: give a spectrum or --film, not both");
            for (int nm = spectral::kMinNm; nm <= spectral::kMaxNm; ++nm) object[nm] = optics::bubble_reflectance(1.0, 1.33, opt.film_nm, nm, 1.0);
            object_name = "soap film " + std::to_string(static_cast<int>(opt.film_nm)) + " nm";
        } else {
            if (opt.names.empty()) throw UsageError("spectra lod: give a spectrum or --film");
            const spectral::NamedSpectrum named = find_spectrum(opt.names.front(), opt.library);
            object = named.spectrum;
            object_name = named.name;
        }
        if (opt.lower < 360 || opt.upper > 830 || opt.upper - opt.lower < 10)
            throw UsageError("--lower/--upper must lie in 360..830 nm (the CMF tables), at least 10 nm apart");
        const spectral::Spectrum light = find_spectrum(opt.light, opt.library).spectrum;
        const spectral::Observer observer = spectral::load_observer(opt.observer);
        const auto colour = [&](int spacing) {
            const spectral::Vec3 white = spectral::spectrum_to_xyz_lod(light, observer, opt.lower, opt.upper, spacing);
            const spectral::Vec3 xyz = spectral::spectrum_to_xyz_lod(light * object, observer, opt.lower, opt.upper, spacing);
            return std::pair{xyz, spectral::xyz_to_lab(xyz, white)};
        };
        const auto full = colour(1).second;
        if (!opt.json)
            std::printf("%s under %s, %s, %d-%d nm\n\n| level | spacing nm | support points | x | y | dE*ab to level 9 |\n"
                        "| --- | --- | --- | --- | --- | --- |\n",
                        object_name.c_str(), opt.light.c_str(), observer.name.c_str(), opt.lower, opt.upper);
        for (int level = spectral::kLodLevels; level >= 1; --level) {
            const int spacing = spectral::lod_spacing(level);
            const int points = (opt.upper - opt.lower) / spacing + 1 + ((opt.upper - opt.lower) % spacing != 0 ? 1 : 0);
            const auto [xyz, lab] = colour(spacing);
            const auto xy = spectral::chromaticity(xyz);
            const double error = spectral::delta_e_ab(lab, full);
            if (opt.json)
                std::cout << nlohmann::json{{"object", object_name}, {"light", opt.light}, {"level", level}, {"spacing_nm", spacing},
                                            {"support_points", points}, {"XYZ", xyz}, {"xy", xy}, {"delta_e_ab", error}}
                                 .dump()
                          << "\n";
            else
                std::printf("| %d | %d | %d | %.4f | %.4f | %.3f |\n", level, spacing, points, xy[0], xy[1], error);
        }
        return 0;
    };

    CLI::App* lod = spectra->add_subcommand("lod", "Colour error of each level of detail (support points every 2^(9-level) nm)");
    lod->add_option("spectrum", o->names, "Object reflectance: library name, file or source (omit with --film)")->expected(0, 1);
    lod->add_option("--light", o->light, "Light spectrum")->capture_default_str();
    lod->add_option("--film", o->film_nm, "Object = a soap film (n = 1.33, in air, normal incidence) this thick, in nm")->check(finite_range(0.0, 10000.0));
    lod->add_option("--observer", o->observer, "1931 (2 degree) or 1964 (10 degree)")->capture_default_str();
    lod->add_option("--lower", o->lower, "Lowest wavelength (nm)")->capture_default_str();
    lod->add_option("--upper", o->upper, "Highest wavelength (nm)")->capture_default_str();
    lod->add_flag("--json", o->json, "Print one JSON object per level");

    auto film = std::make_shared<FilmErrorOptions>();
    CLI::App* film_error = spectra->add_subcommand(
        "film-error", "CIEDE2000 of thin films by the Fourier series (per order) against the 1 nm transfer-matrix integral");
    film_error->add_option("--orders", film->orders, "Series orders to study")->capture_default_str()->delimiter(',');
    film_error->add_option("--light", film->light, "Light spectrum (library name)")->capture_default_str();
    film_error->add_option("--observer", film->observer, "1931 (2 degree) or 1964 (10 degree)")->capture_default_str();
    film_error->add_option("--thickness-step", film->thickness_step, "Thickness step (nm)")->capture_default_str();
    film_error->add_option("--max-thickness", film->max_thickness, "Thickest film (nm)")->capture_default_str();
    film_error->add_option("--angle-step", film->angle_step, "Angle step (degrees; 89 is always included)")->capture_default_str();
    film_error->add_flag("--json", film->json, "Print the table as JSON");

    return [o, list, xyz, pack, cmf, plot, lod, run_lod, film, film_error, uplift] {
        if (lod->parsed()) return run_lod(*o);
        if (film_error->parsed()) {
            film->library = o->library;
            return run_film_error(*film);
        }
        if (uplift->parsed() && o->rgb.empty() == o->environment.empty())
            throw UsageError("spectra uplift: give R,G,B or --environment FILE, one of them");
        if (uplift->parsed() && !o->environment.empty()) {
            const lighting::Environment environment = lighting::make_environment(o->environment, 256);  // as the effects get it
            const lighting::SpectralForm& form = *environment.spectral;
            const spectral::Observer observer = spectral::load_observer("1931");
            nlohmann::json spectra = nlohmann::json::array();
            std::vector<spectral::Spectrum> curves(3);
            for (size_t k = 0; k < 3; ++k) {
                for (int nm = lighting::SpectralForm::kFirstNm; nm <= lighting::SpectralForm::kLastNm; ++nm)
                    curves[k][nm] = form.spectra[k][static_cast<size_t>(nm - lighting::SpectralForm::kFirstNm)];
                const spectral::Vec3 xyz = spectral::spectrum_to_xyz(curves[k], observer);
                const auto xy = spectral::chromaticity(xyz);
                spectra.push_back({{"xy", {xy[0], xy[1]}}, {"luminance", xyz[1]}});
            }
            if (!o->out.empty()) {
                std::ofstream csv(o->out);
                csv << "nm,s0,s1,s2\n";
                for (int nm = lighting::SpectralForm::kFirstNm; nm <= lighting::SpectralForm::kLastNm; ++nm)
                    csv << nm << "," << curves[0][nm] << "," << curves[1][nm] << "," << curves[2][nm] << "\n";
                if (!csv) throw Error(o->out + ": cannot write");
            }
            if (o->json) {
                std::cout << nlohmann::json{{"environment", o->environment}, {"uplifted", form.texels_only}, {"projection_error", form.projection_error},
                                            {"disc_lights", environment.discs.size()}, {"spectra", spectra}}
                                 .dump(2)
                          << "\n";
            } else {
                std::printf("%s: %s; %zu disc light(s) (a sun or lamp, shaded apart)\n", o->environment.c_str(),
                            form.texels_only ? "colours uplifted (Jakob & Hanika 2019), held by three spectra of its own" : "spectra from its model",
                            environment.discs.size());
                if (form.texels_only)
                    std::printf("three spectra hold its texels' own spectra within %.1f %% RMS%s\n", 100.0 * form.projection_error,
                                form.projection_error > 0.05 ? " (above 5 %: films and gratings under it may be several CIEDE2000 off)" : "");
                for (size_t k = 0; k < 3; ++k)
                    std::printf("  spectrum %zu: x %.4f, y %.4f, luminance %.3g\n", k, spectra[k]["xy"][0].get<double>(), spectra[k]["xy"][1].get<double>(),
                                spectra[k]["luminance"].get<double>());
            }
            return 0;
        }
        if (uplift->parsed()) {
            const std::vector<double> c = parse_doubles("rgb", o->rgb, 3);
            const spectral::Observer observer = spectral::load_observer("1931");
            const spectral::UpliftFit fit(observer);
            const spectral::UpliftedRadiance u = spectral::uplift_radiance({c[0], c[1], c[2]});
            spectral::Spectrum s;
            for (int nm = spectral::UpliftFit::kFirstNm; nm <= spectral::UpliftFit::kLastNm; ++nm) s[nm] = u.value(nm, fit.illuminant());
            const spectral::Vec3 xyz = spectral::spectrum_to_xyz(s, observer);
            const spectral::Vec3 back = spectral::xyz_to_linear_srgb_unclipped(xyz);
            const double m = std::max({c[0], c[1], c[2], 1e-300});
            // CIEDE2000 of the colour and its round trip, both scaled so that the largest channel is 1.
            const auto lab = [&](const spectral::Vec3& rgb) { return fit.lab_of_rgb({rgb[0] / m, rgb[1] / m, rgb[2] / m}); };
            const double error = spectral::delta_e_2000(lab({std::max(c[0], 0.0), std::max(c[1], 0.0), std::max(c[2], 0.0)}), lab(back));
            if (!o->out.empty()) {
                std::ofstream csv(o->out);
                csv << "nm,value\n";
                for (int nm = spectral::UpliftFit::kFirstNm; nm <= spectral::UpliftFit::kLastNm; ++nm) csv << nm << "," << s[nm] << "\n";
                if (!csv) throw Error(o->out + ": cannot write");
            }
            const auto xy = spectral::chromaticity(xyz);
            if (o->json) {
                std::cout << nlohmann::json{{"rgb", c}, {"scale", u.scale}, {"coefficients", {u.shape.c0, u.shape.c1, u.shape.c2}},
                                            {"xy", {xy[0], xy[1]}}, {"rgb_back", {back[0], back[1], back[2]}}, {"delta_e2000", error}}
                                 .dump(2)
                          << "\n";
            } else {
                std::printf("spectrum of %s: 2m S(c0 t^2 + c1 t + c2) D65(nm), m = %g (the largest channel), t = (nm - 360) / 470,\n"
                            "  S(x) = 1/2 + x / (2 sqrt(1 + x^2)); c = %.6g, %.6g, %.6g\n",
                            o->rgb.c_str(), u.scale / 2.0, u.shape.c0, u.shape.c1, u.shape.c2);
                std::printf("colour back: %.6g, %.6g, %.6g (x %.5f, y %.5f); CIEDE2000 %.3g from the colour asked for\n", back[0], back[1], back[2],
                            xy[0], xy[1], error);
                for (int nm = 380; nm <= 780; nm += 40) std::printf("  %d nm  %.5g\n", nm, s[nm]);
            }
            return 0;
        }
        if (list->parsed()) {
            const spectral::SpectralLibrary library = spectral::load_library(o->library);
            nlohmann::json entries = nlohmann::json::array();
            for (size_t i = 0; i < library.entries.size(); ++i) {
                const auto& e = library.entries[i];
                entries.push_back({{"index", i}, {"name", e.named.name}, {"kind", e.kind}, {"source", e.named.source}});
                if (!o->json)
                    std::printf("%3zu  %-12s %-12s %s\n", i, e.named.name.c_str(), e.kind.c_str(), e.named.source.c_str());
            }
            if (o->json) std::cout << nlohmann::json{{"library", library.path}, {"spectra", entries}}.dump(2) << "\n";
            return 0;
        }
        if (xyz->parsed()) {
            const spectral::NamedSpectrum s = find_spectrum(o->names.front(), o->library);
            const spectral::Observer observer = spectral::load_observer(o->observer);
            const spectral::Vec3 value = spectral::spectrum_to_xyz(s.spectrum, observer, {o->lower, o->upper, o->step});
            const auto xy = spectral::chromaticity(value);
            const spectral::Vec3 rgb = spectral::xyz_to_linear_srgb(value, parse_mapping(o->mapping));
            std::array<int, 3> srgb8{};
            for (int c = 0; c < 3; ++c) srgb8[c] = static_cast<int>(std::lround(spectral::srgb_encode(rgb[c]) * 255));
            if (o->json) {
                std::cout << nlohmann::json{{"spectrum", s.name}, {"source", s.source}, {"observer", observer.name},
                                            {"range_nm", {o->lower, o->upper, o->step}}, {"XYZ", value}, {"xy", xy},
                                            {"linear_srgb", rgb}, {"srgb8", srgb8}, {"mapping", o->mapping}}
                                 .dump()
                          << "\n";
            } else {
                std::printf("%s (%s, %s)\n  XYZ    %.6f %.6f %.6f\n  xy     %.6f %.6f\n  sRGB   %.6f %.6f %.6f (linear)  %d %d %d (8-bit)\n",
                            s.name.c_str(), s.source.c_str(), observer.name.c_str(), value[0], value[1], value[2], xy[0], xy[1],
                            rgb[0], rgb[1], rgb[2], srgb8[0], srgb8[1], srgb8[2]);
            }
            return 0;
        }
        if (pack->parsed() || cmf->parsed()) {
            const texture::PixelFormat format = parse_storage(o->format);
            spectral::PackedTexture packed;
            if (pack->parsed()) packed = spectral::pack_spectra(spectral::load_library(o->library).spectra(), format);
            else packed = spectral::cmf_texture(spectral::load_observer("1931"), spectral::load_observer("1964"), format);
            write_texture(packed, o->out);
            std::cout << "wrote " << o->out << " (" << packed.texture.width() << "x" << packed.texture.height() << ", "
                      << texture::format_name(format) << ", scale " << packed.scale << ")\n";
            return 0;
        }
        if (plot->parsed()) {
            std::vector<spectral::NamedSpectrum> spectra;
            for (const auto& name : o->names) spectra.push_back(find_spectrum(name, o->library));
            PlotOptions options;
            const auto x = o->size.find('x');
            if (x == std::string::npos) throw UsageError("--size: expected WxH");
            options.width = std::stoi(o->size.substr(0, x));
            options.height = std::stoi(o->size.substr(x + 1));
            if (options.width < 300 || options.height < 200 || options.width > 8000 || options.height > 8000)
                throw UsageError("--size: the chart needs at least 300x200 (and at most 8000x8000)");
            if (o->lower < spectral::kMinNm || o->upper > spectral::kMaxNm || o->upper - o->lower < 10)
                throw UsageError("--lower/--upper must lie in 300..900 nm, at least 10 nm apart");
            options.lower_nm = o->lower;
            options.upper_nm = o->upper;
            options.normalise = o->normalise;
            const auto chart = plot_spectra(spectra, spectral::load_observer("1931"), options);
            image::write_image(o->out, chart, image::Encoding::Srgb);
            std::cout << "wrote " << o->out << "\n";
            return 0;
        }
        return 2;
    };
}

}  // namespace fxview::app
